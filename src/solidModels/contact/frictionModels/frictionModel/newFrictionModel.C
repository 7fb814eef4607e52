/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "frictionModel.H"
#include "fvMesh.H"

Foam::autoPtr<Foam::frictionModel> Foam::frictionModel::New
(
    const fvPatch& patch,
    const dictionary& patchDict
)
{
    const word modelType
    (
        patchDict.getOrDefault<word>("friction", "frictionless")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(patchDict)
            << "Unknown friction model " << modelType
            << " in entry 'friction' of " << patchDict.name() << nl << nl
            << "Valid friction models:" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    // Finite deformation: the tangential laws are not validated there yet
    // (the finite-strain patch test with coulomb missed its uniform state
    // by 1.5e-3); only frictionless contact is offered (issue 22)
    const fvMesh& mesh = patch.boundaryMesh().mesh();
    const bool nonlinearGeometry =
        mesh.solutionDict().found("solidMechanics")
     && mesh.solutionDict().subDict("solidMechanics").lookupOrDefault<bool>
        (
            "nonlinearGeometry", false
        );
    if (nonlinearGeometry && modelType != "frictionless")
    {
        FatalIOErrorInFunction(patchDict)
            << "Friction model " << modelType << " in entry 'friction' of "
            << patchDict.name() << " is not available with"
            << " 'nonlinearGeometry yes' in "
            << mesh.solutionDict().subDict("solidMechanics").name()
            << " (not validated under finite deformation yet)."
            << " Valid there: friction frictionless"
            << exit(FatalIOError);
    }

    // An absent <friction>Coeffs is an empty one, named where it would be,
    // so that errors about its entries point at the right place
    const dictionary coeffs(patchDict.subOrEmptyDict(modelType + "Coeffs"));

    Info<< "Contact patch " << patch.name()
        << ": selecting friction model " << modelType << endl;

    return autoPtr<frictionModel>(cstrIter()(patch, coeffs));
}


// ************************************************************************* //
