/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "neoHookean.H"
#include "finiteStrainFields.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace solidMaterialLaws
{
    defineTypeNameAndDebug(neoHookean, 0);
    addToRunTimeSelectionTable(solidMaterialLaw, neoHookean, dictionary);
}
}

const Foam::Enum<Foam::solidMaterialLaws::neoHookean::form>
Foam::solidMaterialLaws::neoHookean::formNames
({
    { form::simo, "simo" },
    { form::decoupled, "decoupled" },
});


namespace
{

Foam::finiteStrainFields::PK1 law
(
    const c4f::elasticity::Lame& lame,
    const Foam::solidMaterialLaws::neoHookean::form form
)
{
    // An iterate's F with J <= 0 has no neo-Hookean stress (ln J, J^-2/3):
    // Hooke's of the same gradient keeps the corrector going
    // (finiteStrainFields)
    const bool decoupled =
        (form == Foam::solidMaterialLaws::neoHookean::form::decoupled);
    return [lame, decoupled](const Eigen::Matrix3d& F) -> Eigen::Matrix3d
    {
        using namespace c4f::elasticity;
        if (checkJacobian(F) == JacobianCheck::ok)
        {
            return
                decoupled
              ? decoupledNeoHookeanPK1(F, lame)
              : neoHookeanPK1(F, lame);
        }
        return stress(Eigen::Matrix3d(F.transpose() - Eigen::Matrix3d::Identity()), lame);
    };
}

} // End anonymous namespace


Foam::solidMaterialLaws::neoHookean::neoHookean
(
    const word& lawType,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    solidMaterialLaw(lawType, mesh, dict),
    E_(coeffs_.get<scalar>("E")),
    nu_(coeffs_.get<scalar>("nu")),
    lame_(),
    form_(form::simo)
{
    const word formName
    (
        coeffs_.lookupOrDefault<word>("form", formNames[form::simo])
    );
    if (!formNames.found(formName))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry 'form' = " << formName << " in " << coeffs_.name()
            << " is invalid. Valid: " << flatOutput(formNames.sortedToc())
            << " (simo: tau = mu (b - I) + lambda ln J I; decoupled: the"
            << " Abaqus/CalculiX NEO HOOKE)"
            << exit(FatalIOError);
    }
    form_ = formNames.get(formName);

    using namespace c4f::elasticity;

    const ConstantsCheck chk = checkConstants(E_, nu_);
    if (chk != ConstantsCheck::ok)
    {
        const bool badE = (chk == ConstantsCheck::nonPositiveE);
        FatalIOErrorInFunction(coeffs_)
            << "Entry '" << (badE ? "E" : "nu") << "' = " << (badE ? E_ : nu_)
            << " in " << coeffs_.name() << " is invalid: "
            << describe(chk).c_str()
            << (badE ? "" : " (a compressible neo-Hookean needs nu < 0.5:"
                " lambda = nu E/((1 + nu)(1 - 2 nu)) is infinite at 0.5)")
            << exit(FatalIOError);
    }
    if (coeffs_.lookupOrDefault<bool>("planeStress", false))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry 'planeStress' = yes in " << coeffs_.name()
            << " is invalid: the neoHookean law has no plane-stress form."
            << " Valid: planeStress no (plane strain on a 2D mesh, or 3D)"
            << exit(FatalIOError);
    }

    lame_ = lameFromEngineering(E_, nu_, false);

    Info<< "    neo-Hookean (" << formNames[form_] << "): E = " << E_ << ", nu = " << nu_
        << " (mu = " << lame_.mu << ", lambda = " << lame_.lambda
        << "), K = 2mu + lambda = " << implicitStiffness(lame_) << endl;
}


Foam::tmp<Foam::volScalarField>
Foam::solidMaterialLaws::neoHookean::impK() const
{
    return uniformField
    (
        "impK",
        dimensionedScalar
        (
            "impK", dimPressure, c4f::elasticity::implicitStiffness(lame_)
        )
    );
}


Foam::tmp<Foam::scalarField>
Foam::solidMaterialLaws::neoHookean::impK(const label patchi) const
{
    return tmp<scalarField>
    (
        new scalarField
        (
            mesh_.boundary()[patchi].size(),
            c4f::elasticity::implicitStiffness(lame_)
        )
    );
}


Foam::tmp<Foam::volSymmTensorField>
Foam::solidMaterialLaws::neoHookean::sigma(const volTensorField& gradD) const
{
    return finiteStrainFields::cauchy(gradD, law(lame_, form_));
}


Foam::tmp<Foam::symmTensorField>
Foam::solidMaterialLaws::neoHookean::sigma
(
    const tensorField& gradD,
    const label
) const
{
    return finiteStrainFields::cauchy(gradD, law(lame_, form_));
}


Foam::tmp<Foam::volTensorField>
Foam::solidMaterialLaws::neoHookean::firstPiola
(
    const volTensorField& gradD
) const
{
    return finiteStrainFields::firstPiola(gradD, law(lame_, form_));
}


Foam::tmp<Foam::tensorField>
Foam::solidMaterialLaws::neoHookean::firstPiola
(
    const tensorField& gradD,
    const label
) const
{
    return finiteStrainFields::firstPiola(gradD, law(lame_, form_));
}

// ************************************************************************* //
