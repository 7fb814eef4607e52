/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "solidContactFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "volPointInterpolation.H"
#include "emptyFvPatch.H"
#include "wedgeFvPatch.H"
#include "solidPatchTractions.H"
#include "aitkenRelaxation.H"
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
    cond_.setSize(patch().size());

    // A restart continues from the written active set and pressure
    if (dict_.found("contactPressure"))
    {
        cond_.pressure = scalarField("contactPressure", dict_, patch().size());
        cond_.explicitPressure = cond_.pressure;
    }
    if (dict_.found("contactActive"))
    {
        cond_.active = activeFlags
        (
            scalarField("contactActive", dict_, patch().size())
        );
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
}


const Foam::scalarField& Foam::solidContactFvPatchVectorField::relaxTarget
(
    const scalarField& newTarget
)
{
    if (target_.size() != newTarget.size())
    {
        target_ = newTarget;
        return target_;
    }

    const scalarField r(newTarget - target_);

    if (residual_.size() != r.size())
    {
        omega_ = omega0_;
    }
    else if (aitken_)
    {
        c4f::coupling::AitkenSums sums;
        forAll(r, facei)
        {
            c4f::coupling::accumulate(sums, residual_[facei], r[facei]);
        }
        reduce(sums.rPrevDotDiff, sumOp<scalar>());
        reduce(sums.diffSqr, sumOp<scalar>());
        omega_ = c4f::coupling::aitkenFactor(omega_, sums, 0.02, 1);
    }

    target_ += omega_*r;
    residual_ = r;
    return target_;
}


void Foam::solidContactFvPatchVectorField::updateSlave()
{
    const clockTime timer;

    const fvMesh& mesh = patch().boundaryMesh().mesh();
    const label timeIndex = mesh.time().timeIndex();
    if (timeIndex != timeIndex_)
    {
        timeIndex_ = timeIndex;
        nCorrectors_ = 0;
        updateTime_ = 0;
        normalForce_ = GREAT;

        // The last step's target is a good start; its residual history
        // belongs to another load
        residual_.clear();
    }
    ++nCorrectors_;

    const solidContactFvPatchVectorField& master = shadow();

    if (!pair_.valid())
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
    }

    // 1. Both surfaces in the current configuration, and the projection
    const volVectorField& D =
        db().lookupObject<volVectorField>(internalField().name());
    const tmp<pointVectorField> tpointD =
        volPointInterpolation::New(mesh).interpolate(D);

    const vectorField Df(*this);
    pair_->update(master, Df, tpointD());

    // 2. The state of the last solve, against the relaxed target
    const vectorField& n = pair_->normal();
    const scalarField Dn(n & Df);

    contactSlaveState state;
    state.currentGap = pair_->gap();

    // A face held in the last solve is judged by where that solve put it
    // against the surface it was held to; a free face by the surface now
    state.solvedGap = state.currentGap;
    if (target_.size() == Dn.size())
    {
        forAll(Dn, facei)
        {
            if (cond_.active[facei])
            {
                state.solvedGap[facei] = Dn[facei] - target_[facei];
            }
        }
    }
    state.gap = Dn - relaxTarget(Dn - pair_->gap());
    state.normal = n;
    state.K = solidPatchTractions::impK(patch());
    state.h = cellSizeNormal();
    state.delta = 1.0/patch().deltaCoeffs();
    state.inRange = pair_->inRange();

    const vectorField ns(patch().nf());
    state.reaction =
        ((ns & solidPatchTractions::sigma(patch())) & state.normal);

    // 3. The method's decision
    method_->correct(state, cond_);

    // 4. The direction-mixed coefficients
    valueFraction() = cond_.valueFraction*sqr(n);
    refValue() = Df - state.gap*n;
    refGrad() =
        (
            cond_.explicitPressure*n
          - solidPatchTractions::explicitNormalTraction(patch())
        )/state.K;

    // 5. The balancing force on the master
    pressure_ = cond_.pressure;
    traction_ = pressure_*n;
    normalForcePrev_ = normalForce_;
    normalForce_ = gSum(pressure_*patch().magSf());
    masterTraction_ =
        pair_->masterForce(traction_*patch().magSf())/master.patch().magSf();

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
            << "  omega = " << omega_
            << "  F_N = " << gSum(pressure_*patch().magSf())
            << "  max|g| = " << gMax(mag(state.currentGap)) << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidContactFvPatchVectorField::solidContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    directionMixedFvPatchVectorField(p, iF),
    dict_(),
    shadowPatchName_(),
    master_(false),
    searchDistance_(-1),
    normals_("faces"),
    rebuildTolerance_(0),
    method_(),
    pair_(),
    cond_(),
    masterTraction_(),
    timeIndex_(-1),
    nCorrectors_(0),
    updateTime_(0),
    normalForce_(GREAT),
    normalForcePrev_(GREAT),
    omega0_(0.3),
    aitken_(true),
    omega_(0.3),
    target_(),
    residual_(),
    traction_(p.size(), Zero),
    pressure_(p.size(), 0)
{
    refValue() = Zero;
    refGrad() = Zero;
    valueFraction() = Zero;
}


Foam::solidContactFvPatchVectorField::solidContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    directionMixedFvPatchVectorField(p, iF),
    dict_(dict),
    shadowPatchName_(dict.get<word>("shadowPatch")),
    master_(dict.get<bool>("master")),
    searchDistance_(dict.getOrDefault<scalar>("searchDistance", -1)),
    normals_(dict.getOrDefault<word>("normals", "faces")),
    rebuildTolerance_(dict.getOrDefault<scalar>("rebuildTolerance", 0)),
    method_(),
    pair_(),
    cond_(),
    masterTraction_(),
    timeIndex_(-1),
    nCorrectors_(0),
    updateTime_(0),
    normalForce_(GREAT),
    normalForcePrev_(GREAT),
    omega0_(dict.getOrDefault<scalar>("couplingRelaxation", 0.3)),
    aitken_(dict.getOrDefault<bool>("aitken", true)),
    omega_(omega0_),
    target_(),
    residual_(),
    traction_(p.size(), Zero),
    pressure_(p.size(), 0)
{
    if (!(omega0_ > 0 && omega0_ <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "Invalid couplingRelaxation " << omega0_ << " in "
            << dict.name() << ": it must lie in (0, 1]" << exit(FatalIOError);
    }

    checkPatch(dict);
    checkShadowEntry(dict);

    if (master_)
    {
        // A restart continues from the written force
        if (dict.found("contactTraction"))
        {
            traction_ = vectorField("contactTraction", dict, p.size());
        }

        if (dict.found("method"))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'method' of " << dict.name() << " on the master"
                << " patch: the method is chosen on the slave patch ("
                << shadowPatchName_ << ", master no)" << exit(FatalIOError);
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

    // A restart continues from the written direction-mixed state, so that
    // the face gradient, and with it the reaction read back in the first
    // corrector, is the one the run was written with
    if (dict.found("valueFraction"))
    {
        refValue() = vectorField("refValue", dict, p.size());
        refGrad() = vectorField("refGradient", dict, p.size());
        valueFraction() =
            symmTensorField("valueFraction", dict, p.size());
    }
    else
    {
        refValue() = *this;
        refGrad() = Zero;
        valueFraction() = Zero;
    }
}


Foam::solidContactFvPatchVectorField::solidContactFvPatchVectorField
(
    const solidContactFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    directionMixedFvPatchVectorField(ptf, p, iF, mapper),
    dict_(ptf.dict_),
    shadowPatchName_(ptf.shadowPatchName_),
    master_(ptf.master_),
    searchDistance_(ptf.searchDistance_),
    normals_(ptf.normals_),
    rebuildTolerance_(ptf.rebuildTolerance_),
    method_(),
    pair_(),
    cond_(),
    masterTraction_(),
    timeIndex_(-1),
    nCorrectors_(0),
    updateTime_(0),
    normalForce_(GREAT),
    normalForcePrev_(GREAT),
    omega0_(ptf.omega0_),
    aitken_(ptf.aitken_),
    omega_(ptf.omega0_),
    target_(),
    residual_(),
    traction_(p.size(), Zero),
    pressure_(p.size(), 0)
{
    // The mapped (e.g. decomposed) patch starts from the mapped state
    traction_.map(ptf.traction_, mapper);

    if (!master_)
    {
        method_ = contactMethod::New(patch(), dict_);
        cond_.setSize(p.size());
        if (ptf.cond_.pressure.size() == ptf.size())
        {
            cond_.pressure.map(ptf.cond_.pressure, mapper);
            cond_.explicitPressure.map(ptf.cond_.explicitPressure, mapper);
            scalarField am(p.size(), 0);
            am.map(activeFraction(ptf.cond_.active), mapper);
            cond_.active = activeFlags(am);
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
    directionMixedFvPatchVectorField(ptf, iF),
    dict_(ptf.dict_),
    shadowPatchName_(ptf.shadowPatchName_),
    master_(ptf.master_),
    searchDistance_(ptf.searchDistance_),
    normals_(ptf.normals_),
    rebuildTolerance_(ptf.rebuildTolerance_),
    method_(),
    pair_(),
    cond_(ptf.cond_),
    masterTraction_(ptf.masterTraction_),
    timeIndex_(ptf.timeIndex_),
    nCorrectors_(ptf.nCorrectors_),
    updateTime_(ptf.updateTime_),
    normalForce_(ptf.normalForce_),
    normalForcePrev_(ptf.normalForcePrev_),
    omega0_(ptf.omega0_),
    aitken_(ptf.aitken_),
    omega_(ptf.omega_),
    target_(ptf.target_),
    residual_(ptf.residual_),
    traction_(ptf.traction_),
    pressure_(ptf.pressure_)
{
    if (!master_)
    {
        method_ = contactMethod::New(patch(), dict_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidContactFvPatchVectorField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    if (master_)
    {
        const solidContactFvPatchVectorField& slave = shadow();

        // Before the slave's first update the force is the one written
        // with the time started from (zero at a fresh start)
        if (slave.masterTraction().size() == patch().size())
        {
            traction_ = slave.masterTraction();
        }
        pressure_ = -(traction_ & patch().nf());

        valueFraction() = Zero;
        refValue() = *this;
        refGrad() =
            (
                traction_
              - solidPatchTractions::explicitNormalTraction(patch())
            )/solidPatchTractions::impK(patch());

        setOutputFields
        (
            scalarField(patch().size(), 0),
            pos(pressure_)
        );
    }
    else
    {
        updateSlave();
    }

    directionMixedFvPatchVectorField::updateCoeffs();
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

    reduce(r.normalForce, sumOp<scalar>());
    reduce(r.tangentialForce, sumOp<scalar>());
    reduce(r.contactArea, sumOp<scalar>());
    reduce(r.maxPressure, maxOp<scalar>());
    reduce(r.maxPenetration, maxOp<scalar>());
    reduce(r.activeFaces, sumOp<label>());
    r.correctors = returnReduce(nCorrectors_, maxOp<label>());
    r.activeSetChanges = returnReduce(cond_.nChanged, sumOp<label>());
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

    const label changes = returnReduce(cond_.nChanged, sumOp<label>());
    const scalar dF = mag(normalForce_ - normalForcePrev_);
    return
        changes == 0
     && dF <= tolerance*max(mag(normalForce_), VSMALL);
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
        << "  changes = " << r.activeSetChanges
        << "  contactTime = " << r.updateTime << " s";
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
        os.writeEntry("couplingRelaxation", omega0_);
        os.writeEntry("normals", normals_);
        os.writeEntry("rebuildTolerance", rebuildTolerance_);
        os.writeEntry("aitken", Switch(aitken_));
        if (dict_.found("searchDistance"))
        {
            os.writeEntry("searchDistance", searchDistance_);
        }
        if (cond_.pressure.size() == patch().size())
        {
            cond_.pressure.writeEntry("contactPressure", os);
            activeFraction(cond_.active).writeEntry("contactActive", os);
        }
    }
    refValue().writeEntry("refValue", os);
    refGrad().writeEntry("refGradient", os);
    valueFraction().writeEntry("valueFraction", os);
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
