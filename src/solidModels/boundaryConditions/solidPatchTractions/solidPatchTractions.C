/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "solidPatchTractions.H"
#include "hyperelasticLaws.H"
#include "eigenFoamConversions.H"
#include "volFields.H"
#include "mechanicalModel.H"

namespace
{

void checkSolverFields(const Foam::fvPatch& patch)
{
    using namespace Foam;
    const fvMesh& mesh = patch.boundaryMesh().mesh();

    // A silent zero here would turn every traction condition into a
    // wrong one, so a solver that does not register the fields is an error
    if
    (
        !mesh.foundObject<volTensorField>("gradD")
     || !mesh.foundObject<volSymmTensorField>("sigma")
    )
    {
        FatalErrorInFunction
            << "Patch " << patch.name()
            << " needs the registered fields 'gradD' and 'sigma'"
            << " (volTensorField, volSymmTensorField);"
            << " use it with solidContactFoam" << exit(FatalError);
    }
}

} // End anonymous namespace


Foam::tmp<Foam::scalarField>
Foam::solidPatchTractions::impK(const fvPatch& patch)
{
    const fvMesh& mesh = patch.boundaryMesh().mesh();
    return mechanicalModel::New(mesh).law().impK(patch.index());
}


const Foam::fvPatchField<Foam::symmTensor>&
Foam::solidPatchTractions::sigma(const fvPatch& patch)
{
    checkSolverFields(patch);
    return patch.lookupPatchField<volSymmTensorField, symmTensor>("sigma");
}


Foam::tmp<Foam::vectorField>
Foam::solidPatchTractions::explicitNormalTraction(const fvPatch& patch)
{
    checkSolverFields(patch);

    const fvPatchTensorField& gradD =
        patch.lookupPatchField<volTensorField, tensor>("gradD");
    const fvPatchSymmTensorField& sigma =
        patch.lookupPatchField<volSymmTensorField, symmTensor>("sigma");

    const vectorField n(patch.nf());

    // Under nonlinearGeometry the solver registers P^T as stressFlux: the
    // traction per reference area is N & P^T (the reference mesh's N)
    const fvMesh& mesh = patch.boundaryMesh().mesh();
    if (mesh.foundObject<volTensorField>("stressFlux"))
    {
        const fvPatchTensorField& flux =
            patch.lookupPatchField<volTensorField, tensor>("stressFlux");
        return (n & flux) - impK(patch)*(n & gradD);
    }
    return (n & sigma) - impK(patch)*(n & gradD);
}


Foam::tmp<Foam::vectorField>
Foam::solidPatchTractions::faceCorrection(const fvPatch& patch)
{
    const fvMesh& mesh = patch.boundaryMesh().mesh();
    if (!mesh.foundObject<volTensorField>("gradD"))
    {
        return tmp<vectorField>(new vectorField(patch.size(), Zero));
    }
    const volTensorField& gradD = mesh.lookupObject<volTensorField>("gradD");

    // fvPatch::delta() is the normal part (n.d) n of d in v1912
    const vectorField k(patch.Cf() - patch.Cn() - patch.delta());
    return k & tensorField(gradD.primitiveField(), patch.faceCells());
}


Foam::tmp<Foam::tensorField>
Foam::solidPatchTractions::cellFluxStress(const fvPatch& patch)
{
    const fvMesh& mesh = patch.boundaryMesh().mesh();
    if (finiteDeformation(mesh))
    {
        return patch.lookupPatchField<volTensorField, tensor>("stressFlux")
            .patchInternalField();
    }
    const symmTensorField s(sigma(patch).patchInternalField());
    tmp<tensorField> tX(new tensorField(s.size()));
    forAll(s, i)
    {
        tX.ref()[i] = tensor(s[i]);
    }
    return tX;
}


bool Foam::solidPatchTractions::finiteDeformation(const fvMesh& mesh)
{
    return mesh.foundObject<volTensorField>("stressFlux");
}


Foam::tmp<Foam::scalarField>
Foam::solidPatchTractions::areaRatio(const fvPatch& patch)
{
    tmp<scalarField> tr(new scalarField(patch.size(), 1.0));
    const fvMesh& mesh = patch.boundaryMesh().mesh();
    if
    (
        !mesh.foundObject<volTensorField>("stressFlux")
     || !mesh.foundObject<volTensorField>("gradD")
    )
    {
        return tr;
    }
    const fvPatchTensorField& gradD =
        patch.lookupPatchField<volTensorField, tensor>("gradD");
    const vectorField N(patch.nf());
    scalarField& r = tr.ref();
    forAll(r, facei)
    {
        const Eigen::Matrix3d F =
            c4f::elasticity::deformationGradient
            (
                c4fConvert::toEigen(gradD[facei])
            );
        if
        (
            c4f::elasticity::checkJacobian(F)
         == c4f::elasticity::JacobianCheck::ok
        )
        {
            r[facei] =
                c4f::elasticity::areaRatio(F, c4fConvert::toEigen(N[facei]));
        }
    }
    return tr;
}


// ************************************************************************* //
