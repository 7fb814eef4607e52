/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "solidContactFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "emptyFvPatch.H"
#include "wedgeFvPatch.H"
#include "solidPatchTractions.H"
#include "contactFvMesh.H"
#include "clockTime.H"

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


//- The active flags as 1/0, the form they are written and mapped in
Foam::scalarField activeFraction(const Foam::boolList& active)
{
    Foam::scalarField a(active.size(), 0);
    forAll(active, facei)
    {
        a[facei] = active[facei] ? 1 : 0;
    }
    return a;
}


//- The smallest gap over the faces in range, over all processors (GREAT
//  where none is in range)
Foam::scalar minGapInRange
(
    const Foam::scalarField& gap,
    const Foam::boolList& inRange
)
{
    Foam::scalar g = Foam::GREAT;
    forAll(gap, facei)
    {
        if (inRange[facei])
        {
            g = Foam::min(g, gap[facei]);
        }
    }
    return Foam::returnReduce(g, Foam::minOp<Foam::scalar>());
}


//- The active flags back from their 1/0 form (mapped values may blend)
Foam::boolList activeFlags(const Foam::scalarField& a)
{
    Foam::boolList active(a.size());
    forAll(a, facei)
    {
        active[facei] = a[facei] > 0.5;
    }
    return active;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::solidContactFvPatchVectorField::checkPatch
(
    const dictionary& dict
) const
{
    if (isA<emptyFvPatch>(patch()) || isA<wedgeFvPatch>(patch()))
    {
        FatalIOErrorInFunction(dict)
            << "Patch " << patch().name() << " of type " << patch().type()
            << " cannot carry the condition solidContact (" << dict.name()
            << "): contact needs a patch of type patch or wall"
            << exit(FatalIOError);
    }

    // On a 2D mesh the faces must lie across the solution plane: a face
    // whose normal has a part in the empty direction is not a contact
    // surface of the plane problem
    const fvMesh& mesh = patch().boundaryMesh().mesh();
    const Vector<label>& solD = mesh.solutionD();
    const vectorField n(patch().nf());
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solD[d] == -1 && n.size() && max(mag(n.component(d))) > 1e-6)
        {
            FatalIOErrorInFunction(dict)
                << "Patch " << patch().name() << " (" << dict.name()
                << ") has faces whose normal points in the empty direction "
                << vector::componentNames[d] << " of this 2D mesh"
                << " (max |n_" << vector::componentNames[d] << "| = "
                << max(mag(n.component(d))) << "); a contact patch must"
                << " be normal to the solution plane" << exit(FatalIOError);
        }
    }

    if (normals_ != "faces" && normals_ != "smoothed")
    {
        FatalIOErrorInFunction(dict)
            << "Invalid normals " << normals_ << " in " << dict.name()
            << ": valid are faces (the master face normal) and smoothed"
            << " (interpolated point normals)" << exit(FatalIOError);
    }

    if (!contactConstraintGroups::sideNames.found(constraintFaces_))
    {
        FatalIOErrorInFunction(dict)
            << "Invalid constraintFaces " << constraintFaces_ << " in "
            << dict.name() << ": valid are "
            << contactConstraintGroups::sideNames.sortedToc()
            << " (slave: one constraint per slave face; master: one per"
            << " master face; auto: per master face where the slave is"
            << " much stiffer)" << exit(FatalIOError);
    }

    if (!(rebuildTolerance_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Invalid rebuildTolerance " << rebuildTolerance_ << " in "
            << dict.name() << ": it must be a length >= 0 [m]"
            << " (0 rebuilds the search tree every corrector)"
            << exit(FatalIOError);
    }

    if (shadowPatchName_ == patch().name())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'shadowPatch " << shadowPatchName_ << "' of "
            << dict.name() << " names the patch itself; it must name the"
            << " other patch of the contact pair" << exit(FatalIOError);
    }

    if (patch().boundaryMesh().findPatchID(shadowPatchName_) < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'shadowPatch " << shadowPatchName_ << "' of "
            << dict.name() << ": there is no patch " << shadowPatchName_
            << nl << "Valid patches: " << patch().boundaryMesh().mesh().boundaryMesh().names()
            << exit(FatalIOError);
    }

    if (searchDistance_ != -1 && !(searchDistance_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Invalid searchDistance " << searchDistance_ << " in "
            << dict.name() << ": it must be a positive length [m]"
            << exit(FatalIOError);
    }
}


void Foam::solidContactFvPatchVectorField::checkShadowEntry
(
    const dictionary& dict
) const
{
    // The boundaryField dictionary holds the shadow's entry when D was read
    // from a file; the field-level check in shadow() covers the rest
    if (dict.parent() == dictionary::null)
    {
        return;
    }
    const dictionary& bf = dict.parent();
    const dictionary* sdictPtr = bf.findDict(shadowPatchName_);
    if (!sdictPtr)
    {
        return;
    }
    const dictionary& sdict = *sdictPtr;

    const word shadowType(sdict.getOrDefault<word>("type", word::null));
    if (shadowType != typeName)
    {
        FatalIOErrorInFunction(sdict)
            << "The shadowPatch " << shadowPatchName_ << " of "
            << dict.name() << " has type '" << shadowType
            << "'; it must be " << typeName << " too, with shadowPatch "
            << patch().name() << exit(FatalIOError);
    }

    const word back(sdict.getOrDefault<word>("shadowPatch", word::null));
    if (back != patch().name())
    {
        FatalIOErrorInFunction(sdict)
            << "Entry 'shadowPatch " << back << "' of " << sdict.name()
            << " does not name " << patch().name() << ", whose shadowPatch"
            << " it is; the two patches must name each other"
            << exit(FatalIOError);
    }

    if (sdict.found("master"))
    {
        const bool shadowMaster = sdict.get<bool>("master");
        if (shadowMaster == master_)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'master " << (master_ ? "yes" : "no") << "' of "
                << dict.name() << " equals that of its shadowPatch "
                << shadowPatchName_ << "; exactly one patch of a pair is"
                << " the master: set 'master yes' on one and 'master no'"
                << " on the other" << exit(FatalIOError);
        }
    }
}


const Foam::solidContactFvPatchVectorField&
Foam::solidContactFvPatchVectorField::shadow() const
{
    const label shadowi =
        patch().boundaryMesh().findPatchID(shadowPatchName_);

    const volVectorField& D =
        db().lookupObject<volVectorField>(internalField().name());

    const solidContactFvPatchVectorField* sp =
        isA<solidContactFvPatchVectorField>(D.boundaryField()[shadowi])
      ? &refCast<const solidContactFvPatchVectorField>
        (
            D.boundaryField()[shadowi]
        )
      : nullptr;

    if (!sp || sp->shadowPatchName_ != patch().name() || sp->master_ == master_)
    {
        FatalIOErrorInFunction(dict_)
            << "The shadowPatch " << shadowPatchName_ << " of "
            << dict_.name() << " must be a solidContact patch of "
            << internalField().name() << " whose shadowPatch is "
            << patch().name() << ", with the other value of 'master'"
            << exit(FatalIOError);
    }
    return *sp;
}


Foam::tmp<Foam::scalarField>
Foam::solidContactFvPatchVectorField::cellSizeNormal() const
{
    const fvMesh& mesh = patch().boundaryMesh().mesh();
    return
        scalarField(mesh.V().field(), patch().faceCells())/patch().magSf();
}


Foam::scalar
Foam::solidContactFvPatchVectorField::defaultSearchDistance() const
{
    const scalarField h(cellSizeNormal());
    return 10*returnReduce(h.size() ? max(h) : 0, maxOp<scalar>());
}


void Foam::solidContactFvPatchVectorField::initSlave()
{
    method_ = contactMethod::New(patch(), dict_);
    friction_ = frictionModel::New(patch(), dict_);
    if (friction_->slips() && !method_->allowsSlip())
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'friction " << friction_->frictionName() << "' of "
            << dict_.name() << " with method " << method_->methodName()
            << ": this method has no slip law (a regularised multiplier"
            << " cannot carry a slip traction; Wriggers 2006, remark"
            << " 2.7.3); valid friction models with it are frictionless"
            << " and stick" << exit(FatalIOError);
    }
    if (method_->augmentsMultipliers())
    {
        friction_->augmentMultipliers();
    }
    cond_.setSize(patch().size());

    // A restart continues from the written active set, pressure and the
    // method's and friction model's state
    method_->state().read(dict_);
    friction_->state().read(dict_);
    if (dict_.found("contactPressure"))
    {
        cond_.pressure = scalarField("contactPressure", dict_, patch().size());
        pressure_ = cond_.pressure;
    }
    if (dict_.found("contactActive"))
    {
        cond_.active = activeFlags
        (
            scalarField("contactActive", dict_, patch().size())
        );
        cond_.coupled = cond_.active;
    }
}


void Foam::solidContactFvPatchVectorField::setOutputFields
(
    const scalarField& gap,
    const scalarField& active
)
{
    const fvMesh& mesh = patch().boundaryMesh().mesh();
    const label patchi = patch().index();

    outputField<scalar>(mesh, "contactPressure", dimPressure)
        .boundaryFieldRef()[patchi] == pressure_;
    outputField<scalar>(mesh, "contactGap", dimLength)
        .boundaryFieldRef()[patchi] == gap;
    outputField<vector>(mesh, "contactTraction", dimPressure)
        .boundaryFieldRef()[patchi] == traction_;
    outputField<scalar>(mesh, "contactActive", dimless)
        .boundaryFieldRef()[patchi] == active;

    // The method's and the friction model's state, where they have one
    // (e.g. contactMultiplier, contactStick, contactSlip)
    if (method_.valid())
    {
        for (const contactFaceState* ms : {&method_->state(), &friction_->state()})
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


void Foam::solidContactFvPatchVectorField::registerInterface()
{
    if (registered_)
    {
        return;
    }

    const contactFvMesh* mesh =
        dynamic_cast<const contactFvMesh*>(&patch().boundaryMesh().mesh());
    if (!mesh)
    {
        FatalErrorInFunction
            << "Patch " << patch().name() << " of " << internalField().name()
            << ": the condition solidContact couples the two bodies inside"
            << " the D matrix and needs the solver's mesh type "
            << contactFvMesh::typeName << " (as solidContactFoam creates"
            << " it); this application's mesh is a plain fvMesh"
            << exit(FatalError);
    }
    mesh->addContactInterface(patch().index(), contactInterface_);
    registered_ = true;
}


const Foam::contactInterfaceCoupling*
Foam::solidContactFvPatchVectorField::coupling() const
{
    // A copy of the field (a previous iterate) has no pair of its own
    if (master_ && !db().foundObject<volVectorField>(internalField().name()))
    {
        return nullptr;
    }
    const solidContactFvPatchVectorField& slave = master_ ? shadow() : *this;
    return slave.coupling_.valid() ? &slave.coupling_() : nullptr;
}


Foam::tmp<Foam::vectorField>
Foam::solidContactFvPatchVectorField::contactForce(const vectorField& D)
{
    vectorField Fs, Fm;
    scalarField ps;
    coupling()->forces(D, Fs, Fm, ps);
    return tmp<vectorField>(new vectorField(master_ ? Fm : Fs));
}


void Foam::solidContactFvPatchVectorField::setCoefficients
(
    const vectorField& F,
    const vectorField& diag
)
{
    const scalarField KS(solidPatchTractions::impK(patch())*patch().magSf());

    // The Laplacian's boundary flux is intCoeffs D_P - bouCoeffs plus the
    // interface's sum_j a n_k^2 D_j. fvMatrix::solveSegregated adds the
    // bouCoeffs of a non-coupled patch to the source and then the
    // interface's sum at the current D once more (it is meant to cancel a
    // coupled patch's patchNeighbourField term); so bouCoeffs carries
    // that sum with the other sign: with F = sum_j a ((D_j - D_P).n + b) n
    // at the current D, F + diag D_P is the explicit part plus that sum.
    gradInternal_ = -diag/KS;
    gradBoundary_ =
        (
            F
          + cmptMultiply(diag, patchInternalField())
          - explicitTraction_*patch().magSf()
        )/KS;

    gradient() =
        (F/patch().magSf() - explicitTraction_)
       /solidPatchTractions::impK(patch());
}


void Foam::solidContactFvPatchVectorField::updateSlave()
{
    const clockTime timer;

    const fvMesh& mesh = patch().boundaryMesh().mesh();
    const label timeIndex = mesh.time().timeIndex();
    if (timeIndex != timeIndex_)
    {
        timeIndex_ = timeIndex;
        method_->beginStep();
        multiplierHistory_.clear();
        nCorrectors_ = 0;
        updateTime_ = 0;
        normalForce_ = GREAT;
    }
    ++nCorrectors_;

    const solidContactFvPatchVectorField& master = shadow();

    const bool newStep = nCorrectors_ == 1;
    const bool firstUpdate = !pair_.valid();
    if (firstUpdate)
    {
        if (searchDistance_ < 0)
        {
            searchDistance_ = defaultSearchDistance();
        }
        pair_.reset
        (
            new contactPatchPair
            (
                patch(), master.patch(), searchDistance_,
                normals_ == "smoothed", rebuildTolerance_
            )
        );
        coupling_.reset
        (
            new contactInterfaceCoupling
            (
                pair_(),
                contactConstraintGroups::sideNames[constraintFaces_]
            )
        );
    }

    // 1. Both surfaces in the current configuration, and the projection
    const vectorField Df(*this);
    pair_->update(master, Df);

    // 2. The reaction of the current state, from its face values and
    // gradient: the last solve's pressure, or the pressure of the state
    // the outer loop set (an accelerated iterate); so the method's decision
    // depends on the current D alone, not on how it was reached
    explicitTraction_ = solidPatchTractions::explicitNormalTraction(patch());
    if (!firstUpdate)
    {
        traction_ =
            solidPatchTractions::impK(patch())*gradient() + explicitTraction_;
        pressure_ = traction_ & pair_->normal();
    }

    // 3. The state
    contactSlaveState state;
    state.gap = pair_->gap();
    state.normal = pair_->normal();
    state.K = solidPatchTractions::impK(patch());
    state.h = cellSizeNormal();
    state.delta = 1.0/patch().deltaCoeffs();
    state.reaction = pressure_;
    state.traction = traction_;
    // A tangential law needs the relative displacement at the same point on
    // both faces: the face values corrected to each overlap's centroid by
    // the cells' gradients (exact for linear fields); frictionless faces
    // need neither
    List<List<vector>> stickCorrection;
    if (friction_->hasTangentialLaw())
    {
        state.relative =
            Df - pair_->slaveValues(pair_->masterFaceDisplacement());

        const word gradName("gradD");
        const tensorField slaveGrad
        (
            patch().lookupPatchField<volTensorField, tensor>(gradName)
           .patchInternalField()
        );
        const tensorField masterGrad
        (
            pair_->gatherMaster
            (
                master.patch().lookupPatchField<volTensorField, tensor>
                (
                    gradName
                ).patchInternalField()()
            )
        );
        stickCorrection = pair_->overlapCorrections(slaveGrad, masterGrad);
        const List<scalarList>& w = pair_->overlapWeights();
        forAll(stickCorrection, i)
        {
            forAll(stickCorrection[i], k)
            {
                state.relative[i] -= w[i][k]*stickCorrection[i][k];
            }
        }
    }
    state.inRange = pair_->inRange();
    state.stiffness = state.K/state.h;
    {
        const fvPatch& mp = master.patch();
        const scalarField masterKh
        (
            solidPatchTractions::impK(mp)*mp.magSf()
           /scalarField(mesh.V().field(), mp.faceCells())
        );
        state.masterStiffness = pair_->slaveValues(masterKh);
        state.pairStiffness =
            1.0/(1.0/state.stiffness + 1.0/max(state.masterStiffness, SMALL));
    }
    if (method_->usesCellStress())
    {
        // The cells' own stress, not the face value the last traction set
        state.cellStress =
            solidPatchTractions::sigma(patch()).patchInternalField();
        state.masterCellStress = pair_->slaveValues
        (
            solidPatchTractions::sigma(master.patch()).patchInternalField()()
        );
    }

    // 4. The method's decision, then the friction model's on the faces the
    // method coupled; a new load step first commits the friction history
    // of the converged state it starts from
    if (newStep)
    {
        friction_->beginStep(state, cond_);
    }
    method_->correct(state, cond_);
    friction_->correct(state, cond_);
    lastState_ = state;

    // 5. The coupling of this corrector
    const fvPatch& mp = master.patch();

    contactInterfaceCoupling::inputs in;
    in.coupled = cond_.coupled;
    in.compliance = cond_.compliance;
    in.pressure0 = cond_.explicitPressure;
    in.gap = state.gap;
    in.normal = state.normal;
    in.slaveK = state.K;
    in.slaveDelta = state.delta;
    in.slaveC = explicitTraction_;
    in.masterK = pair_->gatherMaster(solidPatchTractions::impK(mp)());
    in.masterDelta = pair_->gatherMaster(scalarField(1.0/mp.deltaCoeffs()));
    in.masterC =
        pair_->gatherMaster(solidPatchTractions::explicitNormalTraction(mp)());
    in.slaveDf = Df;
    in.masterDf = pair_->masterFaceDisplacement();
    in.masterMagSf = pair_->gatherMaster(mp.magSf());
    in.tied = cond_.tied;
    if (friction_->hasTangentialLaw())
    {
        in.stickPoint = friction_->state().field<vector>("contactStickPoint");
        in.stickCorrection.transfer(stickCorrection);
    }
    in.tangentialTraction = cond_.tangentialTraction;
    in.tangentialMultiplier = cond_.tangentialMultiplier;
    in.D = &primitiveField();

    coupling_->set(in);

    // 6. This patch's matrix coefficients
    setCoefficients(contactForce(primitiveField()), coupling_->slaveDiag());

    // The force this corrector starts from: its change in the corrector is
    // part of the convergence test
    normalForce_ = gSum(pressure_*patch().magSf());

    setOutputFields(pair_->gap(), activeFraction(cond_.active));

    updateTime_ += timer.elapsedTime();

    if
    (
        mesh.solutionDict().subOrEmptyDict("solidMechanics")
       .getOrDefault<bool>("verbose", false)
    )
    {
        Info<< "    contact " << patch().name() << ": corrector "
            << nCorrectors_ << "  active = "
            << returnReduce(label(std::count(cond_.active.begin(), cond_.active.end(), true)), sumOp<label>())
            << "  changes = " << returnReduce(cond_.nChanged, sumOp<label>())
            << "  F_N = " << normalForce_
            << "  max|g| = " << gMax(mag(state.gap))
            << "  minGap = " << minGapInRange(state.gap, state.inRange)
            << "  masterFaceConstraints = " << coupling_->nConstraintGroups()
            << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidContactFvPatchVectorField::solidContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    contactLduInterfaceHolder(p),
    fixedGradientFvPatchVectorField(p, iF),
    lduInterfaceField(contactInterface_),
    dict_(),
    shadowPatchName_(),
    master_(false),
    searchDistance_(-1),
    normals_("faces"),
    rebuildTolerance_(0),
    constraintFaces_("auto"),
    method_(),
    friction_(),
    pair_(),
    coupling_(),
    cond_(),
    timeIndex_(-1),
    nCorrectors_(0),
    updateTime_(0),
    normalForce_(GREAT),
    registered_(false),
    gradInternal_(),
    gradBoundary_(),
    explicitTraction_(),
    traction_(p.size(), Zero),
    pressure_(p.size(), 0)
{}


Foam::solidContactFvPatchVectorField::solidContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    contactLduInterfaceHolder(p),
    fixedGradientFvPatchVectorField(p, iF),
    lduInterfaceField(contactInterface_),
    dict_(dict),
    shadowPatchName_(dict.get<word>("shadowPatch")),
    master_(dict.get<bool>("master")),
    searchDistance_(dict.getOrDefault<scalar>("searchDistance", -1)),
    normals_(dict.getOrDefault<word>("normals", "faces")),
    rebuildTolerance_(dict.getOrDefault<scalar>("rebuildTolerance", 0)),
    constraintFaces_(dict.getOrDefault<word>("constraintFaces", "auto")),
    method_(),
    friction_(),
    pair_(),
    coupling_(),
    cond_(),
    timeIndex_(-1),
    nCorrectors_(0),
    updateTime_(0),
    normalForce_(GREAT),
    registered_(false),
    gradInternal_(),
    gradBoundary_(),
    explicitTraction_(),
    traction_(p.size(), Zero),
    pressure_(p.size(), 0)
{
    // The relaxed target these entries controlled no longer exists: the
    // interface is implicit in the D matrix
    for (const word obsolete : {"couplingRelaxation", "aitken"})
    {
        if (dict.found(obsolete))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << obsolete << "' of " << dict.name()
                << " is no longer used: the contact interface is implicit"
                << " in the D matrix, with no relaxed target; remove it"
                << " (the outer correctors are accelerated in"
                << " solidMechanics of system/fvSolution)"
                << exit(FatalIOError);
        }
    }

    checkPatch(dict);
    checkShadowEntry(dict);

    if (master_)
    {
        // A restart continues from the written force
        if (dict.found("contactTraction"))
        {
            traction_ = vectorField("contactTraction", dict, p.size());
            pressure_ = -(traction_ & patch().nf());
        }

        for (const word slaveOnly : {"method", "friction"})
        {
            if (dict.found(slaveOnly))
            {
                FatalIOErrorInFunction(dict)
                    << "Entry '" << slaveOnly << "' of " << dict.name()
                    << " on the master patch: the " << slaveOnly
                    << " is chosen on the slave patch (" << shadowPatchName_
                    << ", master no)" << exit(FatalIOError);
            }
        }
    }
    else
    {
        initSlave();
    }

    if (dict.found("value"))
    {
        fvPatchVectorField::operator=(vectorField("value", dict, p.size()));
    }
    else
    {
        fvPatchVectorField::operator=(patchInternalField());
    }

    // A restart continues from the written gradient, so that the face
    // stress of its first corrector is the one the run was written with
    gradient() =
        dict.found("gradient")
      ? vectorField("gradient", dict, p.size())
      : vectorField(p.size(), Zero);
}


Foam::solidContactFvPatchVectorField::solidContactFvPatchVectorField
(
    const solidContactFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    contactLduInterfaceHolder(p),
    fixedGradientFvPatchVectorField(ptf, p, iF, mapper),
    lduInterfaceField(contactInterface_),
    dict_(ptf.dict_),
    shadowPatchName_(ptf.shadowPatchName_),
    master_(ptf.master_),
    searchDistance_(ptf.searchDistance_),
    normals_(ptf.normals_),
    rebuildTolerance_(ptf.rebuildTolerance_),
    constraintFaces_(ptf.constraintFaces_),
    method_(),
    friction_(),
    pair_(),
    coupling_(),
    cond_(),
    timeIndex_(-1),
    nCorrectors_(0),
    updateTime_(0),
    normalForce_(GREAT),
    registered_(false),
    gradInternal_(),
    gradBoundary_(),
    explicitTraction_(),
    traction_(p.size(), Zero),
    pressure_(p.size(), 0)
{
    // The mapped (e.g. decomposed) patch starts from the mapped state
    traction_.map(ptf.traction_, mapper);
    pressure_.map(ptf.pressure_, mapper);

    if (!master_)
    {
        method_ = contactMethod::New(patch(), dict_);
        method_->state().map(ptf.method_->state(), mapper);
        friction_ = frictionModel::New(patch(), dict_);
        friction_->state().map(ptf.friction_->state(), mapper);
        cond_.setSize(p.size());
        if (ptf.cond_.pressure.size() == ptf.size())
        {
            cond_.pressure.map(ptf.cond_.pressure, mapper);
            scalarField am(p.size(), 0);
            am.map(activeFraction(ptf.cond_.active), mapper);
            cond_.active = activeFlags(am);
            cond_.coupled = cond_.active;
        }
    }
}


Foam::solidContactFvPatchVectorField::solidContactFvPatchVectorField
(
    const solidContactFvPatchVectorField& ptf
)
:
    solidContactFvPatchVectorField(ptf, ptf.internalField())
{}


Foam::solidContactFvPatchVectorField::solidContactFvPatchVectorField
(
    const solidContactFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    contactLduInterfaceHolder(ptf.patch()),
    fixedGradientFvPatchVectorField(ptf, iF),
    lduInterfaceField(contactInterface_),
    dict_(ptf.dict_),
    shadowPatchName_(ptf.shadowPatchName_),
    master_(ptf.master_),
    searchDistance_(ptf.searchDistance_),
    normals_(ptf.normals_),
    rebuildTolerance_(ptf.rebuildTolerance_),
    constraintFaces_(ptf.constraintFaces_),
    method_(),
    friction_(),
    pair_(),
    coupling_(),
    cond_(ptf.cond_),
    timeIndex_(ptf.timeIndex_),
    nCorrectors_(ptf.nCorrectors_),
    updateTime_(ptf.updateTime_),
    normalForce_(ptf.normalForce_),
    registered_(false),
    gradInternal_(ptf.gradInternal_),
    gradBoundary_(ptf.gradBoundary_),
    explicitTraction_(ptf.explicitTraction_),
    traction_(ptf.traction_),
    pressure_(ptf.pressure_)
{
    if (!master_)
    {
        method_ = contactMethod::New(patch(), dict_);
        method_->state() = ptf.method_->state();
        friction_ = frictionModel::New(patch(), dict_);
        friction_->state() = ptf.friction_->state();
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::solidContactFvPatchVectorField::~solidContactFvPatchVectorField()
{
    if (registered_)
    {
        dynamic_cast<const contactFvMesh&>(patch().boundaryMesh().mesh())
            .removeContactInterface(patch().index(), contactInterface_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidContactFvPatchVectorField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    registerInterface();

    if (master_)
    {
        // The slave first, so that the coupling is this corrector's
        solidContactFvPatchVectorField& slave =
            const_cast<solidContactFvPatchVectorField&>(shadow());
        slave.updateCoeffs();

        explicitTraction_ =
            solidPatchTractions::explicitNormalTraction(patch());

        if (coupling())
        {
            setCoefficients
            (
                contactForce(primitiveField()),
                coupling()->masterDiag()
            );
        }
        else
        {
            // Before the slave's first update: the written force (zero at
            // a fresh start)
            setCoefficients
            (
                traction_*patch().magSf(),
                vectorField(patch().size(), Zero)
            );
        }

        setOutputFields(scalarField(patch().size(), 0), pos(pressure_));
    }
    else
    {
        updateSlave();
    }

    fixedGradientFvPatchVectorField::updateCoeffs();
}


void Foam::solidContactFvPatchVectorField::evaluate
(
    const Pstream::commsTypes commsType
)
{
    if (!updated())
    {
        updateCoeffs();
    }

    // The tractions and face values of the solve just made, from its cell
    // values: the face values then agree with what the matrix held.
    // updateFromCells sets the values, so fixedGradient's evaluate (which
    // would set them again) is skipped
    updateFromCells();

    fvPatchVectorField::evaluate(commsType);
}


void Foam::solidContactFvPatchVectorField::updateFromCells()
{
    if (coupling())
    {
        const vectorField F(contactForce(primitiveField()));
        traction_ = F/patch().magSf();
        gradient() =
            (traction_ - explicitTraction_)
           /solidPatchTractions::impK(patch());
        pressure_ =
            master_
          ? scalarField(-(traction_ & patch().nf()))
          : scalarField(traction_ & pair_->normal());
    }

    // The face values follow from the cells and the gradient (before the
    // first contact update: the gradient read or initialised)
    Field<vector>::operator=
    (
        patchInternalField() + gradient()/patch().deltaCoeffs()
    );
}


Foam::label Foam::solidContactFvPatchVectorField::activeSetChanges() const
{
    return master_ ? 0 : returnReduce(cond_.nChanged, sumOp<label>());
}


Foam::tmp<Foam::Field<Foam::vector>>
Foam::solidContactFvPatchVectorField::gradientInternalCoeffs() const
{
    if (gradInternal_.size() != size())
    {
        return fixedGradientFvPatchVectorField::gradientInternalCoeffs();
    }
    return tmp<Field<vector>>(new Field<vector>(gradInternal_));
}


Foam::tmp<Foam::Field<Foam::vector>>
Foam::solidContactFvPatchVectorField::gradientBoundaryCoeffs() const
{
    if (gradBoundary_.size() != size())
    {
        return fixedGradientFvPatchVectorField::gradientBoundaryCoeffs();
    }
    return tmp<Field<vector>>(new Field<vector>(gradBoundary_));
}


void Foam::solidContactFvPatchVectorField::updateInterfaceMatrix
(
    solveScalarField& result,
    const bool add,
    const solveScalarField& psiInternal,
    const scalarField&,
    const direction cmpt,
    const Pstream::commsTypes
) const
{
    // The matrix's own coefficients for this patch are the explicit source
    // (see setCoefficients); the coupling's are used instead
    const contactInterfaceCoupling* c = coupling();
    if (!c)
    {
        return;
    }

    const scalarField nb
    (
        master_
      ? c->masterNeighbour(psiInternal, cmpt)
      : c->slaveNeighbour(psiInternal, cmpt)
    );

    // The neighbours enter the matrix product with the sign of an internal
    // face's off-diagonal coefficient
    const scalar sign = add ? 1 : -1;
    const labelUList& fc = patch().faceCells();
    forAll(fc, facei)
    {
        result[fc[facei]] += sign*nb[facei];
    }
}


Foam::solidContactFvPatchVectorField::report
Foam::solidContactFvPatchVectorField::contactReport() const
{
    report r;
    if (master_)
    {
        return r;
    }

    const scalarField& A = patch().magSf();
    const scalarField gap
    (
        pair_.valid() ? pair_->gap() : scalarField(patch().size(), GREAT)
    );
    const vectorField n
    (
        pair_.valid() ? pair_->normal() : vectorField(-patch().nf())
    );

    // F_T is the sum of |t_T| A, each in its own face's frame as F_N is
    // the sum of p_N A, so that full slip gives F_T = mu F_N exactly (the
    // resultant of the tangential forces differs from it by the rotation
    // of the faces' normals: 1.9e-5 on slidingBlock)
    forAll(A, facei)
    {
        const vector F(traction_[facei]*A[facei]);
        const scalar Fn = F & n[facei];
        r.normalForce += Fn;
        r.tangentialForce += mag(F - Fn*n[facei]);
        if (facei < cond_.active.size() && cond_.active[facei])
        {
            r.contactArea += A[facei];
            ++r.activeFaces;
        }
        r.maxPressure = max(r.maxPressure, pressure_[facei]);
        r.maxPenetration = max(r.maxPenetration, -gap[facei]);
    }

    r.minGap =
        pair_.valid() ? minGapInRange(pair_->gap(), pair_->inRange()) : GREAT;

    reduce(r.normalForce, sumOp<scalar>());
    reduce(r.tangentialForce, sumOp<scalar>());
    reduce(r.contactArea, sumOp<scalar>());
    reduce(r.maxPressure, maxOp<scalar>());
    reduce(r.maxPenetration, maxOp<scalar>());
    reduce(r.activeFaces, sumOp<label>());
    r.correctors = returnReduce(nCorrectors_, maxOp<label>());
    r.activeSetChanges = returnReduce(cond_.nChanged, sumOp<label>());
    r.multiplierUpdates = method_->nMultiplierUpdates();
    r.updateTime = returnReduce(updateTime_, maxOp<scalar>());
    return r;
}


bool Foam::solidContactFvPatchVectorField::contactConverged
(
    const scalar tolerance
) const
{
    if (master_)
    {
        return true;
    }

    const label changes = activeSetChanges();

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
    const scalar F = gSum(pressure_*patch().magSf());
    const scalar dF = mag(F - normalForce_);
    const label nActive =
        returnReduce
        (
            label(std::count(cond_.active.begin(), cond_.active.end(), true)),
            sumOp<label>()
        );
    return
        changes == 0
     && (nActive == 0 || dF <= tolerance*max(mag(F), VSMALL));
}


bool Foam::solidContactFvPatchVectorField::updateMultipliers()
{
    if (master_ || !coupling())
    {
        return false;
    }

    // The converged state: the last update's geometry (it changed by less
    // than the tolerance since) and the reaction of the last solve
    lastState_.reaction = pressure_;

    if (method_->state().found("contactMultiplier"))
    {
        multiplierRecord rec;
        rec.update = method_->nMultiplierUpdates();
        rec.multiplier = method_->state()["contactMultiplier"];
        rec.gap = lastState_.gap;
        rec.pressure = pressure_;
        multiplierHistory_.append(rec);
    }

    // The tangential multipliers of an augmenting method are updated with
    // the normal ones, from the same converged state
    lastState_.traction = traction_;
    const bool updated =
        method_->updateMultipliers(lastState_, cond_)
      | friction_->updateMultipliers
        (
            lastState_, cond_, method_->multiplierTolerance()
        );
    if (updated)
    {
        setOutputFields(pair_->gap(), activeFraction(cond_.active));
    }
    return updated;
}


bool Foam::solidContactFvPatchVectorField::multipliersConverged() const
{
    return
        master_
     || (method_->multipliersConverged() && friction_->multipliersConverged());
}


Foam::scalar Foam::solidContactFvPatchVectorField::stepLimit()
{
    // The method is the same on every processor, so all take this branch
    // together
    if (master_ || !coupling() || !method_->limitsStep())
    {
        return 1;
    }

    // The gaps at the current D (the update's), by the same search as a
    // corrector's; lastState_ holds those the corrector started from
    const vectorField Df(*this);
    pair_->update(shadow(), Df);

    const scalar alpha = returnReduce
    (
        method_->stepLimit(lastState_, pair_->gap(), pair_->inRange()),
        minOp<scalar>()
    );

    if (alpha < 1)
    {
        Info<< "    contact " << patch().name() << ": step limited to "
            << alpha << " of the update (minGap "
            << minGapInRange(lastState_.gap, lastState_.inRange)
            << " -> " << minGapInRange(pair_->gap(), pair_->inRange())
            << " m)" << endl;
    }
    return alpha;
}


void Foam::solidContactFvPatchVectorField::autoMap
(
    const fvPatchFieldMapper& m
)
{
    fixedGradientFvPatchVectorField::autoMap(m);
    traction_.autoMap(m);
    pressure_.autoMap(m);
    if (!master_)
    {
        method_->state().autoMap(m);
        friction_->state().autoMap(m);
        if (cond_.pressure.size())
        {
            scalarField am(activeFraction(cond_.active));
            am.autoMap(m);
            cond_.pressure.autoMap(m);
            cond_.setSize(m.size());
            cond_.active = activeFlags(am);
            cond_.coupled = cond_.active;
        }
    }
    // The geometry and the coupling are rebuilt for the new faces
    pair_.clear();
    coupling_.clear();
}


void Foam::solidContactFvPatchVectorField::rmap
(
    const fvPatchVectorField& ptf,
    const labelList& addr
)
{
    fixedGradientFvPatchVectorField::rmap(ptf, addr);

    const solidContactFvPatchVectorField& p =
        refCast<const solidContactFvPatchVectorField>(ptf);
    traction_.rmap(p.traction_, addr);
    pressure_.rmap(p.pressure_, addr);
    if (!master_ && p.cond_.pressure.size() == p.size())
    {
        method_->state().rmap(p.method_->state(), addr);
        friction_->state().rmap(p.friction_->state(), addr);

        cond_.setSize(size());
        cond_.pressure.rmap(p.cond_.pressure, addr);
        scalarField am(activeFraction(cond_.active));
        am.rmap(activeFraction(p.cond_.active), addr);
        cond_.active = activeFlags(am);
        cond_.coupled = cond_.active;
    }
}


Foam::string Foam::solidContactFvPatchVectorField::contactState() const
{
    if (master_)
    {
        return string();
    }

    const report r(contactReport());
    OStringStream os;
    os  << "F_N = " << r.normalForce
        << "  active = " << r.activeFaces
        << "  maxPenetration = " << r.maxPenetration
        << "  minGap = " << r.minGap
        << "  changes = " << r.activeSetChanges;
    if (friction_->hasTangentialLaw())
    {
        const scalarField& stick = friction_->state()["contactStick"];
        os  << "  F_T = " << r.tangentialForce
            << "  stick = "
            << returnReduce(label(std::count(stick.begin(), stick.end(), 1.0)), sumOp<label>())
            << "  slip = "
            << returnReduce(label(std::count(stick.begin(), stick.end(), 0.0)), sumOp<label>());
    }
    if (method_->updatesMultipliers())
    {
        os  << "  multiplierUpdates = " << r.multiplierUpdates;
    }
    os  << "  contactTime = " << r.updateTime << " s";
    return os.str();
}


void Foam::solidContactFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    os.writeEntry("shadowPatch", shadowPatchName_);
    os.writeEntry("master", Switch(master_));

    if (master_)
    {
        traction_.writeEntry("contactTraction", os);
    }
    else
    {
        os.writeEntry("method", method_->methodName());
        method_->write(os);
        os.writeEntry("normals", normals_);
        os.writeEntry("friction", friction_->frictionName());
        friction_->write(os);
        os.writeEntry("rebuildTolerance", rebuildTolerance_);
        os.writeEntry("constraintFaces", constraintFaces_);
        if (dict_.found("searchDistance"))
        {
            os.writeEntry("searchDistance", searchDistance_);
        }
        if (cond_.pressure.size() == patch().size())
        {
            pressure_.writeEntry("contactPressure", os);
            activeFraction(cond_.active).writeEntry("contactActive", os);
        }
        method_->state().write(os);
        friction_->state().write(os);
    }
    gradient().writeEntry("gradient", os);
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * Build Macros  * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchVectorField,
        solidContactFvPatchVectorField
    );
}
