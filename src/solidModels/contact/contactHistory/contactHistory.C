/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactHistory.H"

#include <algorithm>

// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::scalarField Foam::contactHistory::activeFraction(const boolList& active)
{
    scalarField a(active.size(), 0);
    forAll(active, facei)
    {
        a[facei] = active[facei] ? 1 : 0;
    }
    return a;
}


Foam::boolList Foam::contactHistory::activeFlags(const scalarField& a)
{
    boolList active(a.size());
    forAll(a, facei)
    {
        active[facei] = a[facei] > 0.5;
    }
    return active;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::contactHistory::addFields(const bool slave)
{
    // Each side writes what its restart needs; the rest follows from it.
    // The slave's traction too: a restart's first corrector starts from
    // the last solve's traction (friction's trial, the output field of a
    // step that converges in that corrector), as a continuing run does
    fields_.add("contactTraction", vector::zero, dimPressure, true);
    fields_.add("contactPressure", 0, dimPressure, slave);
}


void Foam::contactHistory::selectModels
(
    const fvPatch& patch,
    const dictionary& dict
)
{
    method_ = contactMethod::New(patch, dict);
    friction_ = frictionModel::New(patch, dict);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactHistory::contactHistory(const fvPatch& patch)
:
    fields_(patch.size()),
    explicitTraction_(),
    method_(),
    friction_(),
    cond_()
{
    addFields(true);
}


Foam::contactHistory::contactHistory
(
    const fvPatch& patch,
    const dictionary& dict,
    const bool slave
)
:
    fields_(patch.size()),
    explicitTraction_(),
    method_(),
    friction_(),
    cond_()
{
    addFields(slave);

    if (!slave)
    {
        // A restart continues from the written force
        if (dict.found("contactTraction"))
        {
            fields_.read(dict);
            pressure() = -(traction() & patch.nf());
        }
        return;
    }

    selectModels(patch, dict);
    if (friction_->slips() && !method_->allowsSlip())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'friction " << friction_->frictionName() << "' of "
            << dict.name() << " with method " << method_->methodName()
            << ": this method has no slip law (a regularised multiplier"
            << " cannot carry a slip traction; Wriggers 2006, remark"
            << " 2.7.3); valid friction models with it are frictionless"
            << " and stick" << exit(FatalIOError);
    }
    // A tangential multiplier only where a tied face's law is the normal
    // law's compliance about it (an exact tie has none to augment)
    if (method_->augmentsMultipliers() && !method_->exactTangentialTie())
    {
        friction_->augmentMultipliers();
    }
    cond_.setSize(patch.size());

    // A restart continues from the written active set, pressure and the
    // method's and friction model's state
    method_->state().read(dict);
    friction_->state().read(dict);
    if (dict.found("contactPressure"))
    {
        fields_.read(dict);
        cond_.pressure = pressure();
    }
    if (dict.found("contactActive"))
    {
        cond_.active =
            activeFlags(scalarField("contactActive", dict, patch.size()));
        cond_.coupled = cond_.active;
    }
}


Foam::contactHistory::contactHistory
(
    const contactHistory& h,
    const fvPatch& patch,
    const dictionary& dict
)
:
    fields_(h.fields_),
    explicitTraction_(h.explicitTraction_),
    method_(),
    friction_(),
    cond_(h.cond_)
{
    if (h.slave())
    {
        selectModels(patch, dict);
        method_->state() = h.method_->state();
        friction_->state() = h.friction_->state();
    }
}


Foam::contactHistory::contactHistory
(
    const contactHistory& h,
    const fvPatch& patch,
    const dictionary& dict,
    const fvPatchFieldMapper& m
)
:
    fields_(patch.size()),
    explicitTraction_(),
    method_(),
    friction_(),
    cond_()
{
    // The mapped (e.g. decomposed) patch starts from the mapped state
    fields_.map(h.fields_, m);

    if (h.slave())
    {
        selectModels(patch, dict);
        method_->state().map(h.method_->state(), m);
        friction_->state().map(h.friction_->state(), m);
        cond_.setSize(patch.size());
        if (h.cond_.pressure.size() == h.size())
        {
            cond_.pressure.map(h.cond_.pressure, m);
            scalarField am(patch.size(), 0);
            am.map(activeFraction(h.cond_.active), m);
            cond_.active = activeFlags(am);
            cond_.coupled = cond_.active;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::contactHistory::nActive() const
{
    return returnReduce
    (
        label(std::count(cond_.active.begin(), cond_.active.end(), true)),
        sumOp<label>()
    );
}


Foam::label Foam::contactHistory::activeSetChanges() const
{
    return slave() ? returnReduce(cond_.nChanged, sumOp<label>()) : 0;
}


void Foam::contactHistory::autoMap(const fvPatchFieldMapper& m)
{
    fields_.autoMap(m);
    if (slave())
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
}


void Foam::contactHistory::rmap
(
    const contactHistory& h,
    const labelList& addr
)
{
    fields_.rmap(h.fields_, addr);
    if (slave() && h.cond_.pressure.size() == h.size())
    {
        method_->state().rmap(h.method_->state(), addr);
        friction_->state().rmap(h.friction_->state(), addr);

        cond_.setSize(size());
        cond_.pressure.rmap(h.cond_.pressure, addr);
        scalarField am(activeFraction(cond_.active));
        am.rmap(activeFraction(h.cond_.active), addr);
        cond_.active = activeFlags(am);
        cond_.coupled = cond_.active;
    }
}


void Foam::contactHistory::write(Ostream& os) const
{
    if (!slave())
    {
        fields_.write(os);
        return;
    }
    if (cond_.pressure.size() == size())
    {
        fields_.write(os);
        activeFraction(cond_.active).writeEntry("contactActive", os);
    }
    method_->state().write(os);
    friction_->state().write(os);
}


void Foam::contactHistory::saveCorrector()
{
    snapshot_.reset(new correctorSnapshot(fields_));
    snapshot_->explicitTraction = explicitTraction_;
    snapshot_->cond = cond_;
    if (slave())
    {
        snapshot_->method.reset(new contactFaceState(method_->state()));
        snapshot_->friction.reset(new contactFaceState(friction_->state()));
    }
}


void Foam::contactHistory::restoreCorrector(const bool frozen)
{
    if (!snapshot_.valid())
    {
        return;
    }
    fields_ = snapshot_->fields;
    explicitTraction_ = snapshot_->explicitTraction;
    cond_ = snapshot_->cond;
    cond_.frozen = frozen;
    if (slave())
    {
        method_->state() = snapshot_->method();
        friction_->state() = snapshot_->friction();
    }
}


// ************************************************************************* //
