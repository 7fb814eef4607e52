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
    traction_(Function1<vector>::New("traction", dict)),
    pressure_
    (
        dict.found("pressure")
      ? Function1<scalar>::New("pressure", dict)
      : autoPtr<Function1<scalar>>()
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
    traction_(ptf.traction_.clone()),
    pressure_(ptf.pressure_.clone())
{}


Foam::solidTractionFvPatchVectorField::solidTractionFvPatchVectorField
(
    const solidTractionFvPatchVectorField& ptf
)
:
    fixedGradientFvPatchVectorField(ptf),
    traction_(ptf.traction_.clone()),
    pressure_(ptf.pressure_.clone())
{}


Foam::solidTractionFvPatchVectorField::solidTractionFvPatchVectorField
(
    const solidTractionFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    fixedGradientFvPatchVectorField(ptf, iF),
    traction_(ptf.traction_.clone()),
    pressure_(ptf.pressure_.clone())
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

    tmp<vectorField> ttr(new vectorField(patch().size(), traction_->value(t)));

    if (pressure_.valid())
    {
        ttr.ref() -= pressure_->value(t)*patch().nf();
    }
    return ttr;
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
