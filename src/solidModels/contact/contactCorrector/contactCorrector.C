/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactCorrector.H"
#include "normalContactLaws.H"
#include "contactReporter.H"
#include "solidPatchTractions.H"
#include "fvMesh.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Cell size normal to each face, V/A
Foam::tmp<Foam::scalarField> cellSizeNormal(const Foam::fvPatch& patch)
{
    const Foam::fvMesh& mesh = patch.boundaryMesh().mesh();
    return
        Foam::scalarField(mesh.V().field(), patch.faceCells())
       /patch.magSf();
}

//- The displacement at the face centres: the patch values (the two-point
//  values at the foot of the normal from the cell centre) with the
//  non-orthogonal part of a leaning cell (solidPatchTractions.H)
Foam::tmp<Foam::vectorField> centreDisplacement(const Foam::fvPatchVectorField& D)
{
    return D + Foam::solidPatchTractions::faceCorrection(D.patch());
}

//- The master patch's face-centre displacements; none for a rigid tool
Foam::tmp<Foam::vectorField> masterDisplacement
(
    const Foam::fvPatchVectorField* master
)
{
    return
        master
      ? centreDisplacement(*master)
      : Foam::tmp<Foam::vectorField>(new Foam::vectorField());
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::contactCorrector::beginCorrector
(
    const fvPatch& patch,
    contactHistory& h
)
{
    const label timeIndex = patch.boundaryMesh().mesh().time().timeIndex();
    if (timeIndex != timeIndex_)
    {
        timeIndex_ = timeIndex;
        h.method().beginStep();
        if (tool_.valid())
        {
            tool_->beginStep();
        }
        multiplierHistory_.clear();
        nCorrectors_ = 0;
        updateTime_ = 0;
        searchTime_ = 0;
        normalForce_ = GREAT;
    }
    ++nCorrectors_;
}


void Foam::contactCorrector::build
(
    const fvPatch& slave,
    const fvPatch* master,
    contactSettings& settings
)
{
    // The default reaches ten of the slave's largest cells
    if (settings.searchDistance() < 0)
    {
        const scalarField h(cellSizeNormal(slave));
        settings.setSearchDistance
        (
            10*returnReduce(h.size() ? max(h) : 0, maxOp<scalar>())
        );
    }
    if (settings.rigid())
    {
        if (!tool_.valid())
        {
            tool_ =
                rigidSurface::New
                (
                    settings.rigidSurfaceDict(), slave.boundaryMesh().mesh()
                );
        }
        pair_.reset
        (
            new rigidContactPair(slave, tool_(), settings.searchDistance())
        );
    }
    else
    {
        pair_.reset
        (
            new contactPatchPair
            (
                slave, *master, settings.searchDistance(),
                settings.normals(), settings.rebuildTolerance()
            )
        );
    }
    // A rigid tool has no faces to pose the constraint on
    coupling_.reset
    (
        new contactInterfaceCoupling
        (
            pair_(),
            settings.rigid()
          ? contactConstraintGroups::side::slave
          : contactConstraintGroups::sideNames[settings.constraintFaces()]
        )
    );
}


void Foam::contactCorrector::setTangentialCompliance
(
    const contactMethod& method,
    contactSlaveCondition& cond
)
{
    if (method.exactTangentialTie())
    {
        cond.tangentialCompliance = scalarField(cond.compliance.size(), 0);
    }
    else
    {
        cond.tangentialCompliance = cond.compliance;
    }
}


Foam::label Foam::contactCorrector::waitAtFirstContact
(
    contactSlaveState& s
)
{
    scalar deepest = 0;
    scalar h = 0;
    forAll(s.constraintGap, facei)
    {
        if (s.inRange[facei])
        {
            deepest = max(deepest, -s.constraintGap[facei]);
            h = max(h, s.h[facei]);
        }
    }
    reduce(deepest, maxOp<scalar>());
    reduce(h, maxOp<scalar>());

    label nWaiting = 0;
    forAll(s.constraintGap, facei)
    {
        if
        (
            c4f::contact::waitsAtFirstContact
            (
                s.constraintGap[facei], deepest, h
            )
        )
        {
            s.inRange[facei] = false;
            ++nWaiting;
        }
    }
    return returnReduce(nWaiting, sumOp<label>());
}


Foam::contactSlaveState Foam::contactCorrector::state
(
    const fixedGradientFvPatchVectorField& slave,
    const contactHistory& h,
    const bool patchCellSize,
    List<List<vector>>& stickCorrection
) const
{
    const fvPatch& patch = slave.patch();

    contactSlaveState s;
    s.gap = pair_->gap();
    // The groups are the last coupling's (none before the first): at a
    // converged state the same as the next one's
    if (coupling_.valid())
    {
        s.constraintGap =
            coupling_->groups().constraintGap
            (
                s.gap, h.cond().coupled, s.grouped
            );
    }
    else
    {
        s.constraintGap = s.gap;
        s.grouped = boolList(s.gap.size(), false);
    }
    s.normal = pair_->normal();
    s.K = solidPatchTractions::impK(patch);
    s.h = cellSizeNormal(patch);
    if (patchCellSize)
    {
        const fvMesh& mesh = patch.boundaryMesh().mesh();
        const scalar V =
            gSum(scalarField(mesh.V().field(), patch.faceCells()));
        const scalar A = gSum(patch.magSf());
        s.h = A > 0 ? V/A : 0;
    }
    s.delta = 1.0/patch.deltaCoeffs();
    s.reaction = h.pressure();
    s.traction = h.traction();
    // Frictionless faces need no tangential kinematics (a transfer less)
    if (h.friction().hasTangentialLaw())
    {
        s.relative =
            pair_->relativeDisplacement
            (
                centreDisplacement(slave), stickCorrection
            );
    }
    s.inRange = pair_->inRange();
    s.stiffness = s.K/s.h;
    s.masterStiffness = pair_->masterStiffness();
    s.pairStiffness =
        1.0/(1.0/s.stiffness + 1.0/max(s.masterStiffness, SMALL));
    if (h.method().usesCellStress())
    {
        // The cells' own stress, not the face value the last traction set
        s.cellStress = solidPatchTractions::cellFluxStress(patch);
        s.masterCellStress = pair_->masterCellStress();
    }
    return s;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactCorrector::contactCorrector()
:
    pair_(),
    coupling_(),
    lastState_(),
    timeIndex_(-1),
    nCorrectors_(0),
    updateTime_(0),
    searchTime_(0),
    timer_(),
    normalForce_(GREAT),
    nWaiting_(0),
    multiplierHistory_()
{}


Foam::contactCorrector::contactCorrector(const contactCorrector& c)
:
    pair_(),
    coupling_(),
    lastState_(),
    timeIndex_(c.timeIndex_),
    nCorrectors_(c.nCorrectors_),
    updateTime_(c.updateTime_),
    searchTime_(c.searchTime_),
    timer_(),
    normalForce_(c.normalForce_),
    nWaiting_(c.nWaiting_),
    multiplierHistory_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactCorrector::clearGeometry()
{
    pair_.clear();
    coupling_.clear();
}


void Foam::contactCorrector::limitSelfReach
(
    const fvPatch& patch,
    const fvPatchVectorField* master,
    const vectorField& Df,
    contactSettings& settings
)
{
    // A face that sees its own patch more than half a cell behind it sees
    // the far side of the wall it bounds, not a face pressed into it: no
    // state of a converged step penetrates by half a cell
    const scalarField h(cellSizeNormal(patch));
    const scalarField& g = pair_->gap();
    const boolList& inRange = pair_->inRange();
    scalar wall = GREAT;
    label nThrough = 0;
    forAll(g, facei)
    {
        if (inRange[facei] && g[facei] < -0.5*h[facei])
        {
            wall = min(wall, -g[facei]);
            ++nThrough;
        }
    }
    reduce(wall, minOp<scalar>());
    reduce(nThrough, sumOp<label>());
    if (!nThrough)
    {
        return;
    }

    if (settings.searchDistanceGiven())
    {
        FatalIOErrorInFunction(settings.dict())
            << "Entry 'searchDistance " << settings.searchDistance()
            << "' of " << settings.dict().name() << " (self-contact) reaches"
            << " through the body: " << nThrough << " faces of "
            << patch.name() << " see the patch's far side of a wall "
            << wall << " m behind them. Set searchDistance below the"
            << " thinnest wall, e.g. " << 0.5*wall << exit(FatalIOError);
    }

    const scalar d = 0.5*wall;
    Info<< "    contact " << patch.name() << ": self-contact searchDistance "
        << settings.searchDistance() << " m (the default) reaches through"
        << " a wall " << wall << " m thick; using " << d << " m" << endl;
    settings.setSearchDistance(d);
    build(patch, master ? &master->patch() : nullptr, settings);
    pair_->update(masterDisplacement(master), Df);
}


void Foam::contactCorrector::correct
(
    const fixedGradientFvPatchVectorField& slave,
    const fvPatchVectorField* master,
    contactSettings& settings,
    contactHistory& h
)
{
    timer_.resetTime();
    const fvPatch& patch = slave.patch();
    beginCorrector(patch, h);

    const bool newStep = nCorrectors_ == 1;
    const bool firstUpdate = !pair_.valid();
    if (firstUpdate)
    {
        // A method that needs the bodies apart (the barrier) cannot follow
        // a rigid tool in prescribed motion: the tool takes its whole step
        // at the step's start, so every step's first iterate penetrates it
        // by the step's increment, where the barrier is not defined
        if (settings.rigid() && h.method().traits().openStart)
        {
            FatalIOErrorInFunction(settings.dict())
                << "Method " << h.method().methodName() << " of "
                << settings.dict().name() << " needs the bodies apart at"
                << " every iterate (openStart yes in solidContactFoam"
                << " -listMethods), but a rigid tool (rigidSurface) moves"
                << " its whole load step at the step's start, so the first"
                << " iterate of each step penetrates it by the step's"
                << " increment. Choose a method with openStart no for a"
                << " rigid tool" << exit(FatalIOError);
        }
        build(patch, master ? &master->patch() : nullptr, settings);
    }

    // 1. Both surfaces in the current configuration, and the projection
    const vectorField Df(centreDisplacement(slave));
    {
        const scalar t0 = timer_.elapsedTime();
        pair_->update(masterDisplacement(master), Df);
        if (firstUpdate && settings.selfContact())
        {
            limitSelfReach(patch, master, Df, settings);
        }
        searchTime_ += timer_.elapsedTime() - t0;
    }
    if (newStep)
    {
        pair_->beginStep();
    }

    // 2. The reaction of the current state, from its face values and
    // gradient: the last solve's pressure, or the pressure of the state
    // the outer loop set (an accelerated iterate); so the method's decision
    // depends on the current D alone, not on how it was reached
    h.explicitTraction() = solidPatchTractions::explicitNormalTraction(patch);
    if (!firstUpdate)
    {
        h.traction() =
            solidPatchTractions::impK(patch)*slave.gradient()
          + h.explicitTraction();
        if (settings.selfContact())
        {
            // The face's own law's part of its traction: the rest is the
            // reaction of the faces that press on it
            vectorField Fs, Fm;
            coupling_->forces(slave.primitiveField(), Fs, Fm, h.pressure());
        }
        else
        {
            h.pressure() = h.traction() & pair_->normal();
        }
    }

    // 3. The state
    List<List<vector>> stickCorrection;
    lastState_ = state(slave, h, settings.patchCellSize(), stickCorrection);

    // 4. The method's decision, then the friction model's on the faces the
    // method coupled; a new load step first commits the friction history
    // of the converged state it starts from
    // First contact (no face active): the barrier keeps every gap open
    // (a penetration stops its run), so it has no first overlap to thin.
    // frozen and openStart are the same on every processor, so nActive's
    // reduction is reached by all or none
    contactSlaveCondition& cond = h.cond();
    nWaiting_ =
        cond.frozen || h.method().traits().openStart || h.nActive()
      ? 0
      : waitAtFirstContact(lastState_);
    if (newStep)
    {
        // The condition the last step converged with (a restart reads
        // the normal law's, not this)
        setTangentialCompliance(h.method(), cond);
        h.friction().beginStep
        (
            lastState_, cond, h.method().contactRange(lastState_)
        );
    }
    if (!firstUpdate)
    {
        h.method().updateCorrectorMultipliers(lastState_, cond);
    }
    h.method().correct(lastState_, cond);
    setTangentialCompliance(h.method(), cond);
    h.friction().correct(lastState_, cond);

    // 5. The coupling of this corrector
    contactInterfaceCoupling::inputs in;
    in.coupled = cond.coupled;
    in.compliance = cond.compliance;
    in.tangentialCompliance = cond.tangentialCompliance;
    in.pressure0 = cond.explicitPressure;
    in.gap = lastState_.gap;
    in.normal = lastState_.normal;
    in.slaveK = lastState_.K;
    in.slaveDelta = lastState_.delta;
    in.slaveC = h.explicitTraction();
    in.slaveFaceCorrection = solidPatchTractions::faceCorrection(slave.patch());
    pair_->gatherMasterData
    (
        in.masterK, in.masterDelta, in.masterC, in.masterFaceCorrection,
        in.masterMagSf
    );
    in.slaveDf = Df;
    in.masterDf = pair_->masterFaceDisplacement();
    in.tied = cond.tied;
    if (h.friction().hasTangentialLaw())
    {
        in.stickPoint = h.friction().stickPoints();
        in.stickCorrection.transfer(stickCorrection);
    }
    in.tangentialTraction = cond.tangentialTraction;
    in.tangentialMultiplier = cond.tangentialMultiplier;
    in.D = &slave.primitiveField();

    coupling_->set(in);
}


void Foam::contactCorrector::finish
(
    const fvPatch& slave,
    const contactHistory& h
)
{
    // The force this corrector starts from: its change in the corrector is
    // part of the convergence test
    normalForce_ = gSum(h.pressure()*slave.magSf());

    const contactReporter reporter(slave, h, this);
    reporter.writeFields();

    updateTime_ += timer_.elapsedTime();

    const fvMesh& mesh = slave.boundaryMesh().mesh();
    if
    (
        mesh.solutionDict().subOrEmptyDict("solidMechanics")
       .getOrDefault<bool>("verbose", false)
    )
    {
        reporter.writeCorrectorLine(Info);
    }
}


bool Foam::contactCorrector::converged
(
    const fvPatch& slave,
    const contactHistory& h,
    const scalar tolerance
) const
{
    const label changes = h.activeSetChanges();

    // The change of the normal force in this corrector: from the state it
    // started from to the solve's (the pressures evaluate() just set), the
    // force residual of the fixed-point map, whatever step the outer loop
    // then takes
    //
    // With no active face the law's force is zero and what the faces
    // carry is the solve's residual traction (measured: F_N of 1e-8 to
    // 1e-5 N changing sign every corrector after a lift-off, whose relative
    // change never fell below the tolerance): the residual test covers it,
    // so the force test is left out
    const scalar F = gSum(h.pressure()*slave.magSf());
    const scalar dF = mag(F - normalForce_);
    const label nActive = h.nActive();
    // A corrector that held faces back at first contact has not offered
    // them to the method: a method that entered none of the others (no
    // change) must still see them
    const bool converged =
        changes == 0
     && nWaiting_ == 0
     && (nActive == 0 || dF <= tolerance*max(mag(F), VSMALL))
     && h.method().lawConverged(lastState_, h.pressure());

    if (converged && valid())
    {
        checkPassedThrough(slave);
    }
    return converged;
}


void Foam::contactCorrector::checkPassedThrough(const fvPatch& slave) const
{
    // A face the step carried through the master, out of the search's
    // reach, has no contact and no force: the step would converge to
    // bodies that overlap, so it stops here before anything is written
    scalarField depth;
    const labelList faces(pair_->passedThrough(depth));
    const label n = returnReduce(faces.size(), sumOp<label>());
    if (n == 0)
    {
        return;
    }
    const scalar maxDepth =
        returnReduce(depth.size() ? max(depth) : 0, maxOp<scalar>());
    const Time& time = slave.boundaryMesh().mesh().time();
    FatalErrorInFunction
        << "Contact patch " << slave.name() << " at time "
        << time.timeName() << ": " << n << " of its "
        << returnReduce(slave.size(), sumOp<label>())
        << " faces passed through the master patch "
        << pair_->masterName() << " within the load step: they lie up"
        << " to " << maxDepth << " m behind the master faces they faced at"
        << " the step's start, beyond the search distance "
        << pair_->searchDistance() << " m, where the search sees no"
        << " contact." << nl
        << "Take smaller load steps (deltaT in system/controlDict) so that"
        << " no face moves farther than the search distance in one step,"
        << " or raise searchDistance in the contact patch's entry of the"
        << " displacement field (default: ten of the slave's cells)"
        << exit(FatalError);
}


bool Foam::contactCorrector::updateToolPosition
(
    const fvPatch& slave,
    const contactHistory& h
)
{
    rigidSurface& tool = tool_();
    const vector& e = tool.forceDirection();
    const scalar P =
        gSum((h.traction()*slave.magSf()) & e);
    const scalar t = slave.boundaryMesh().mesh().time().value();
    const scalar s0 = tool.translation(t) & e;
    const bool moved =
        tool.updatePosition
        (
            P, t, coupling_->directionStiffness(e),
            // Within the search's reach of where the faces are now
            0.5*pair_->searchDistance()
        );
    if (moved)
    {
        Info<< "    contact " << slave.name() << ": force control update "
            << tool.nForceUpdates() << ": P = " << P << " N (prescribed "
            << tool.targetForce(t) << "), position " << s0 << " -> "
            << (tool.translation(t) & e) << " m" << endl;
        if (tool.nForceUpdates() > maxForceUpdates_)
        {
            FatalErrorInFunction
                << "Contact patch " << slave.name() << " at time "
                << slave.boundaryMesh().mesh().time().timeName()
                << ": the force-controlled tool's position did not settle"
                << " in " << maxForceUpdates_ << " updates (P = " << P
                << " N, prescribed " << tool.targetForce(t) << " N)"
                << exit(FatalError);
        }
    }
    return moved;
}


bool Foam::contactCorrector::updateMultipliers
(
    const fvPatch& slave,
    contactHistory& h
)
{
    if (!valid())
    {
        return false;
    }

    // The converged state: the last update's geometry (it changed by less
    // than the tolerance since) and the reaction of the last solve
    lastState_.reaction = h.pressure();

    if (const scalarField* lambda = h.method().multipliers())
    {
        multiplierRecord rec;
        rec.update = h.method().nMultiplierUpdates();
        rec.multiplier = *lambda;
        rec.gap = lastState_.gap;
        rec.pressure = h.pressure();
        multiplierHistory_.append(rec);
    }

    // The tangential multipliers of an augmenting method are updated with
    // the normal ones, from the same converged state
    lastState_.traction = h.traction();
    bool updated =
        h.method().updateMultipliers(lastState_, h.cond())
      | h.friction().updateMultipliers
        (
            lastState_, h.cond(), h.method().multiplierTolerance()
        );

    // A force-controlled tool moves once the method's multipliers have
    // settled (its force is that of a converged state with them)
    if
    (
        !updated
     && h.multipliersConverged()
     && tool_.valid()
     && tool_->forceControlled()
    )
    {
        updated = updateToolPosition(slave, h);
    }
    if (updated)
    {
        contactReporter(slave, h, this).writeFields();
    }
    return updated;
}


Foam::scalar Foam::contactCorrector::stepLimit
(
    const fvPatchVectorField& slave,
    const fvPatchVectorField* master,
    const contactHistory& h,
    const bool newtonStep
)
{
    // The method is the same on every processor, so all take this branch
    // together
    if (!valid() || !h.method().limitsStep())
    {
        return 1;
    }

    // The gaps at the current D (the update's), by the same search as a
    // corrector's; lastState_ holds those the corrector started from
    const vectorField Df(centreDisplacement(slave));
    pair_->update(masterDisplacement(master), Df);

    const scalar alpha = returnReduce
    (
        h.method().stepLimit
        (
            lastState_, pair_->gap(), pair_->inRange(), newtonStep
        ),
        minOp<scalar>()
    );

    if (alpha < 1)
    {
        Info<< "    contact " << slave.patch().name() << ": step limited to "
            << alpha << " of the update (minGap "
            << contactReporter::gapText
               (
                   contactReporter::minGap(lastState_.gap, lastState_.inRange)
               ).c_str()
            << " -> "
            << contactReporter::gapText
               (
                   contactReporter::minGap(pair_->gap(), pair_->inRange())
               ).c_str()
            << " m)" << endl;
    }
    return alpha;
}


// ************************************************************************* //
