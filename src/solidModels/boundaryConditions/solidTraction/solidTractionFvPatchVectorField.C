/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "solidTractionFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "solidPatchTractions.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidTractionFvPatchVectorField::solidTractionFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    fixedGradientFvPatchVectorField(p, iF),
    traction_(),
    pressure_()
{
    gradient() = Zero;
}


Foam::solidTractionFvPatchVectorField::solidTractionFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    fixedGradientFvPatchVectorField(p, iF),
    traction_(PatchFunction1<vector>::New(p.patch(), "traction", dict)),
    pressure_
    (
        dict.found("pressure")
      ? PatchFunction1<scalar>::New(p.patch(), "pressure", dict)
      : autoPtr<PatchFunction1<scalar>>()
    )
{
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


Foam::solidTractionFvPatchVectorField::solidTractionFvPatchVectorField
(
    const solidTractionFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    fixedGradientFvPatchVectorField(ptf, p, iF, mapper),
    traction_(ptf.traction_->clone(p.patch()).ptr()),
    pressure_
    (
        ptf.pressure_.valid() ? ptf.pressure_->clone(p.patch()).ptr() : nullptr
    )
{
    // A field-valued traction comes with the old patch's faces
    traction_->autoMap(mapper);
    if (pressure_.valid())
    {
        pressure_->autoMap(mapper);
    }
}


Foam::solidTractionFvPatchVectorField::solidTractionFvPatchVectorField
(
    const solidTractionFvPatchVectorField& ptf
)
:
    fixedGradientFvPatchVectorField(ptf),
    traction_(ptf.traction_->clone(patch().patch()).ptr()),
    pressure_
    (
        ptf.pressure_.valid()
      ? ptf.pressure_->clone(patch().patch()).ptr()
      : nullptr
    )
{}


Foam::solidTractionFvPatchVectorField::solidTractionFvPatchVectorField
(
    const solidTractionFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    fixedGradientFvPatchVectorField(ptf, iF),
    traction_(ptf.traction_->clone(patch().patch()).ptr()),
    pressure_
    (
        ptf.pressure_.valid()
      ? ptf.pressure_->clone(patch().patch()).ptr()
      : nullptr
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField>
Foam::solidTractionFvPatchVectorField::patchImpK() const
{
    return solidPatchTractions::impK(patch());
}


Foam::tmp<Foam::vectorField>
Foam::solidTractionFvPatchVectorField::explicitNormalTraction() const
{
    return solidPatchTractions::explicitNormalTraction(patch());
}


void Foam::solidTractionFvPatchVectorField::setTraction(const vectorField& t)
{
    gradient() = (t - explicitNormalTraction())/patchImpK();
}


Foam::tmp<Foam::vectorField>
Foam::solidTractionFvPatchVectorField::prescribedTraction() const
{
    const scalar t = db().time().timeOutputValue();

    tmp<vectorField> ttr(new vectorField(traction_->value(t)));

    if (pressure_.valid())
    {
        ttr.ref() -= pressure_->value(t)*patch().nf();
    }
    return ttr;
}


void Foam::solidTractionFvPatchVectorField::autoMap
(
    const fvPatchFieldMapper& m
)
{
    fixedGradientFvPatchVectorField::autoMap(m);
    traction_->autoMap(m);
    if (pressure_.valid())
    {
        pressure_->autoMap(m);
    }
}


void Foam::solidTractionFvPatchVectorField::rmap
(
    const fvPatchVectorField& ptf,
    const labelList& addr
)
{
    fixedGradientFvPatchVectorField::rmap(ptf, addr);

    const solidTractionFvPatchVectorField& tptf =
        refCast<const solidTractionFvPatchVectorField>(ptf);
    traction_->rmap(tptf.traction_(), addr);
    if (pressure_.valid() && tptf.pressure_.valid())
    {
        pressure_->rmap(tptf.pressure_(), addr);
    }
}


void Foam::solidTractionFvPatchVectorField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    setTraction(prescribedTraction());

    fixedGradientFvPatchVectorField::updateCoeffs();
}


void Foam::solidTractionFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    traction_->writeData(os);
    if (pressure_.valid())
    {
        pressure_->writeData(os);
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
        solidTractionFvPatchVectorField
    );
}
