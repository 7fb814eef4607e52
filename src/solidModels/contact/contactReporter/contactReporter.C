/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactReporter.H"
#include "contactCorrector.H"
#include "solidPatchTractions.H"
#include "volFields.H"
#include "OStringStream.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The registered output field of the given name, created (zero inside,
//  calculated on every patch, written with each time) on first use
template<class Type>
Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>& outputField
(
    const Foam::fvMesh& mesh,
    const Foam::word& name,
    const Foam::dimensionSet& dims
)
{
    using namespace Foam;
    typedef GeometricField<Type, fvPatchField, volMesh> fieldType;

    if (!mesh.foundObject<fieldType>(name))
    {
        fieldType* fld = new fieldType
        (
            IOobject
            (
                name,
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::AUTO_WRITE
            ),
            mesh,
            dimensioned<Type>(dims, Zero)
        );
        fld->store();
    }
    return mesh.lookupObjectRef<fieldType>(name);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::label Foam::contactReporter::countStick
(
    const scalarField& stick,
    const scalar flag
)
{
    return returnReduce
    (
        label(std::count(stick.begin(), stick.end(), flag)),
        sumOp<label>()
    );
}


Foam::scalar Foam::contactReporter::minGap
(
    const scalarField& gap,
    const boolList& inRange
)
{
    scalar g = GREAT;
    forAll(gap, facei)
    {
        if (inRange[facei])
        {
            g = min(g, gap[facei]);
        }
    }
    return returnReduce(g, minOp<scalar>());
}


Foam::string Foam::contactReporter::gapText(const scalar g)
{
    if (g >= 0.5*GREAT)
    {
        return "none";
    }
    OStringStream os;
    os  << g;
    return os.str();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::contactReporter::setFields
(
    const scalarField& gap,
    const scalarField& active
) const
{
    const fvMesh& mesh = patch_.boundaryMesh().mesh();
    const label patchi = patch_.index();

    // Per current area: under finite deformation the laws' tractions are
    // per reference area (the total-Lagrangian P.N), Nanson's da/dA apart
    const scalarField ratio(solidPatchTractions::areaRatio(patch_));
    outputField<scalar>(mesh, "contactPressure", dimPressure)
        .boundaryFieldRef()[patchi] == shownPressure()/ratio;
    outputField<scalar>(mesh, "contactGap", dimLength)
        .boundaryFieldRef()[patchi] == gap;
    outputField<vector>(mesh, "contactTraction", dimPressure)
        .boundaryFieldRef()[patchi] == history_.traction()/ratio;
    outputField<scalar>(mesh, "contactActive", dimless)
        .boundaryFieldRef()[patchi] == active;

    // The method's and the friction model's state, where they have one
    // (e.g. contactMultiplier, contactStick, contactSlip)
    if (history_.slave())
    {
        for
        (
            const contactFaceState* ms
          : {&history_.method().state(), &history_.friction().state()}
        )
        {
            for (const word& name : ms->names<scalar>())
            {
                outputField<scalar>(mesh, name, ms->dimensions<scalar>(name))
                    .boundaryFieldRef()[patchi] == ms->field<scalar>(name);
            }
            for (const word& name : ms->names<vector>())
            {
                outputField<vector>(mesh, name, ms->dimensions<vector>(name))
                    .boundaryFieldRef()[patchi] == ms->field<vector>(name);
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactReporter::contactReporter
(
    const fvPatch& patch,
    const contactHistory& history,
    const contactCorrector* corrector
)
:
    patch_(patch),
    history_(history),
    corrector_(corrector),
    lastMasterFace_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField> Foam::contactReporter::shownPressure() const
{
    // Self-contact: the history's pressure is the face's own law's part
    // (the method's), the face carries the reaction of the faces that
    // press on it besides
    if (corrector_ && corrector_->hasPair() && corrector_->pair().selfContact())
    {
        return -(history_.traction() & patch_.nf());
    }
    return history_.pressure();
}


void Foam::contactReporter::writeFields() const
{
    if (corrector_)
    {
        setFields
        (
            corrector_->pair().gap(),
            contactHistory::activeFraction(history_.cond().active)
        );
    }
    else
    {
        setFields(scalarField(patch_.size(), 0), pos(history_.pressure()));
    }
}


Foam::contactReporter::row Foam::contactReporter::report() const
{
    row r;
    if (!corrector_)
    {
        return r;
    }

    const bool searched = corrector_->hasPair();
    const scalarField& A = patch_.magSf();
    const scalarField gap
    (
        searched
      ? corrector_->pair().gap()
      : scalarField(patch_.size(), GREAT)
    );
    // Self-contact: each contact pushes on both its sides, which are faces
    // of this patch: the force across it along each face's own inward
    // normal, counted once (half the patch's sum)
    const bool self = searched && corrector_->pair().selfContact();
    const vectorField n
    (
        searched && !self
      ? corrector_->pair().normal()
      : vectorField(-patch_.nf())
    );
    // The gap the constraint closes (per master face where it is posed
    // there), that of the state the last corrector started from
    const scalarField& cg = corrector_->lastState().constraintGap;
    const scalarField& penetrationGap = cg.size() == A.size() ? cg : gap;
    const vectorField& traction = history_.traction();
    const scalarField pressure(shownPressure());
    const boolList& active = history_.cond().active;
    // Forces from the tractions per reference area and the reference
    // areas; the area and the pressure per current area (finite
    // deformation; the ratio is 1 in small strain)
    const scalarField ratio(solidPatchTractions::areaRatio(patch_));

    forAll(A, facei)
    {
        const vector F(traction[facei]*A[facei]);
        const scalar Fn = F & n[facei];
        r.normalForce += Fn;
        r.force += F;
        r.tangentialForce += mag(F - Fn*n[facei]);
        if (facei < active.size() && active[facei])
        {
            r.contactArea += A[facei]*ratio[facei];
            ++r.activeFaces;
        }
        r.maxPressure = max(r.maxPressure, pressure[facei]/ratio[facei]);
        r.maxPenetration = max(r.maxPenetration, -penetrationGap[facei]);
    }

    r.minGap =
        searched
      ? minGap(corrector_->pair().gap(), corrector_->pair().inRange())
      : GREAT;

    if (searched && corrector_->tool())
    {
        // The tool receives -F_i at each face's closest point on it
        const rigidSurface& tool = *corrector_->tool();
        const scalar t = patch_.boundaryMesh().mesh().time().value();
        r.rigid = true;
        r.toolTranslation = tool.translation(t);
        const point c = tool.centreOfRotation() + r.toolTranslation;
        const vectorField& xbar =
            dynamic_cast<const rigidContactPair&>(corrector_->pair()).footPoints();
        forAll(A, facei)
        {
            r.toolMoment -= (xbar[facei] - c) ^ (traction[facei]*A[facei]);
        }
        reduce(r.toolMoment, sumOp<vector>());
    }

    if (self)
    {
        r.normalForce *= 0.5;
        r.tangentialForce *= 0.5;
        r.contactArea *= 0.5;
    }

    reduce(r.normalForce, sumOp<scalar>());
    reduce(r.tangentialForce, sumOp<scalar>());
    reduce(r.force, sumOp<vector>());
    reduce(r.contactArea, sumOp<scalar>());
    reduce(r.maxPressure, maxOp<scalar>());
    reduce(r.maxPenetration, maxOp<scalar>());
    reduce(r.activeFaces, sumOp<label>());
    r.correctors = returnReduce(corrector_->nCorrectors(), maxOp<label>());
    r.activeSetChanges = history_.activeSetChanges();
    r.multiplierUpdates = history_.method().nMultiplierUpdates();
    r.updateTime = returnReduce(corrector_->updateTime(), maxOp<scalar>());
    r.searchTime = returnReduce(corrector_->searchTime(), maxOp<scalar>());
    return r;
}


Foam::string Foam::contactReporter::summary() const
{
    if (!corrector_)
    {
        return string();
    }

    const row r(report());
    OStringStream os;
    os  << "F_N = " << r.normalForce
        << "  active = " << r.activeFaces
        << "  maxPenetration = " << r.maxPenetration
        << "  minGap = " << gapText(r.minGap).c_str()
        << "  changes = " << r.activeSetChanges;
    const frictionModel& friction = history_.friction();
    if (friction.hasTangentialLaw())
    {
        const scalarField& stick = friction.stickFlags();
        os  << "  F_T = " << r.tangentialForce
            << "  stick = " << countStick(stick, 1)
            << "  slip = " << countStick(stick, 0);
    }
    if (history_.method().updatesMultipliers())
    {
        os  << "  multiplierUpdates = " << r.multiplierUpdates;
    }
    os  << "  contactTime = " << r.updateTime << " s"
        << "  searchTime = " << r.searchTime << " s";
    return os.str();
}


void Foam::contactReporter::writeCorrectorLine(Ostream& os) const
{
    const contactSlaveState& state = corrector_->lastState();
    os  << "    contact " << patch_.name() << ": corrector "
        << corrector_->nCorrectors()
        << "  active = " << history_.nActive()
        << "  changes = " << history_.activeSetChanges()
        << "  F_N = " << corrector_->normalForce()
        << "  max|g| = " << gMax(mag(state.gap))
        << "  minGap = " << gapText(minGap(state.gap, state.inRange)).c_str()
        << "  masterFaceConstraints = "
        << corrector_->coupling().nConstraintGroups();

    const labelList& hit = corrector_->pair().masterFace();
    label moved = 0;
    if (lastMasterFace_.size() == hit.size())
    {
        forAll(hit, facei)
        {
            if (hit[facei] != lastMasterFace_[facei])
            {
                ++moved;
            }
        }
    }
    lastMasterFace_ = hit;
    os  << "  projectionsMoved = " << returnReduce(moved, sumOp<label>());

    const frictionModel& friction = history_.friction();
    if (friction.hasTangentialLaw())
    {
        os  << "  stick = " << countStick(friction.stickFlags(), 1);
    }
    os  << endl;
}


// ************************************************************************* //
