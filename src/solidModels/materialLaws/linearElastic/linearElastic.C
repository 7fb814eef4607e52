/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "linearElastic.H"
#include "eigenFoamConversions.H"
#include "finiteStrainFields.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace solidMaterialLaws
{
    defineTypeNameAndDebug(linearElastic, 0);
    addToRunTimeSelectionTable(solidMaterialLaw, linearElastic, dictionary);
}
}


namespace
{

//- Stress of every entry of a tensor field through the kernel
void hookeField
(
    const Foam::tensorField& gradD,
    const c4f::elasticity::Lame& lame,
    const int planeStressAxis,
    Foam::symmTensorField& sigma
)
{
    forAll(gradD, i)
    {
        sigma[i] = Foam::c4fConvert::toFoamSymm
        (
            c4f::elasticity::stress
            (
                Foam::c4fConvert::toEigen(gradD[i]),
                lame,
                planeStressAxis
            )
        );
    }
}

} // End anonymous namespace


Foam::solidMaterialLaws::linearElastic::linearElastic
(
    const word& lawType,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    solidMaterialLaw(lawType, mesh, dict),
    E_(coeffs_.get<scalar>("E")),
    nu_(coeffs_.get<scalar>("nu")),
    planeStress_(coeffs_.lookupOrDefault<bool>("planeStress", false)),
    lame_(),
    planeStressAxis_(-1)
{
    using namespace c4f::elasticity;

    const ConstantsCheck chk = checkConstants(E_, nu_);

    if (chk == ConstantsCheck::nonPositiveE)
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry 'E' = " << E_ << " in " << coeffs_.name()
            << " is invalid: " << describe(chk).c_str()
            << exit(FatalIOError);
    }
    if (chk == ConstantsCheck::nuOutOfRange)
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry 'nu' = " << nu_ << " in " << coeffs_.name()
            << " is invalid: " << describe(chk).c_str()
            << exit(FatalIOError);
    }

    lame_ = lameFromEngineering(E_, nu_, planeStress_);

    if (planeStress_)
    {
        const Vector<label>& geomD = mesh.geometricD();
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (geomD[d] == -1)
            {
                planeStressAxis_ = d;
            }
        }
        if (mesh.nGeometricD() != 2 || planeStressAxis_ < 0)
        {
            FatalIOErrorInFunction(coeffs_)
                << "Entry 'planeStress' = yes in " << coeffs_.name()
                << " needs a 2D mesh (one empty direction), but the mesh has "
                << mesh.nGeometricD() << " geometric directions."
                << " Valid: planeStress no (plane strain or 3D)"
                << exit(FatalIOError);
        }
    }

    Info<< "    E = " << E_ << ", nu = " << nu_
        << (planeStress_ ? ", plane stress" : "")
        << ", K = 2mu + lambda = " << implicitStiffness(lame_) << endl;
}


Foam::tmp<Foam::volScalarField>
Foam::solidMaterialLaws::linearElastic::impK() const
{
    return uniformField
    (
        "impK",
        dimensionedScalar
        (
            "impK",
            dimPressure,
            c4f::elasticity::implicitStiffness(lame_)
        )
    );
}


Foam::tmp<Foam::scalarField>
Foam::solidMaterialLaws::linearElastic::impK(const label patchi) const
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
Foam::solidMaterialLaws::linearElastic::sigma(const volTensorField& gradD) const
{
    tmp<volSymmTensorField> tsigma
    (
        uniformField("sigmaLaw", dimensionedSymmTensor(dimPressure, Zero))
    );
    volSymmTensorField& s = tsigma.ref();

    hookeField
    (
        gradD.primitiveField(), lame_, planeStressAxis_, s.primitiveFieldRef()
    );

    volSymmTensorField::Boundary& sb = s.boundaryFieldRef();
    forAll(sb, patchi)
    {
        hookeField
        (
            gradD.boundaryField()[patchi], lame_, planeStressAxis_, sb[patchi]
        );
    }

    return tsigma;
}


Foam::tmp<Foam::symmTensorField>
Foam::solidMaterialLaws::linearElastic::sigma
(
    const tensorField& gradD,
    const label patchi
) const
{
    tmp<symmTensorField> ts(new symmTensorField(gradD.size()));
    hookeField(gradD, lame_, planeStressAxis_, ts.ref());
    return ts;
}


Foam::tmp<Foam::volTensorField>
Foam::solidMaterialLaws::linearElastic::firstPiola
(
    const volTensorField& gradD
) const
{
    const c4f::elasticity::Lame lame(lame_);
    return finiteStrainFields::firstPiola
    (
        gradD,
        [lame](const Eigen::Matrix3d& F)
        {
            return c4f::elasticity::stVenantKirchhoffPK1(F, lame);
        }
    );
}


Foam::tmp<Foam::tensorField>
Foam::solidMaterialLaws::linearElastic::firstPiola
(
    const tensorField& gradD,
    const label
) const
{
    const c4f::elasticity::Lame lame(lame_);
    return finiteStrainFields::firstPiola
    (
        gradD,
        [lame](const Eigen::Matrix3d& F)
        {
            return c4f::elasticity::stVenantKirchhoffPK1(F, lame);
        }
    );
}


void Foam::solidMaterialLaws::linearElastic::checkGeometry
(
    const bool nonlinearGeometry,
    const dictionary& where
) const
{
    solidMaterialLaw::checkGeometry(nonlinearGeometry, where);

    if (nonlinearGeometry && planeStress_)
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry 'planeStress' = yes in " << coeffs_.name()
            << " cannot be used with 'nonlinearGeometry' yes in "
            << where.name() << ": plane stress is a small-strain reduction"
            << " here. Valid: planeStress no (plane strain), or"
            << " nonlinearGeometry no"
            << exit(FatalIOError);
    }
}
