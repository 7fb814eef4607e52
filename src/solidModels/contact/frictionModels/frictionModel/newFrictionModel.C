/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "frictionModel.H"

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

    // An absent <friction>Coeffs is an empty one, named where it would be,
    // so that errors about its entries point at the right place
    const dictionary coeffs(patchDict.subOrEmptyDict(modelType + "Coeffs"));

    Info<< "Contact patch " << patch.name()
        << ": selecting friction model " << modelType << endl;

    return autoPtr<frictionModel>(cstrIter()(patch, coeffs));
}


// ************************************************************************* //
