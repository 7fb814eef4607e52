/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "solidMaterialLaw.H"

Foam::autoPtr<Foam::solidMaterialLaw> Foam::solidMaterialLaw::New
(
    const fvMesh& mesh,
    const dictionary& dict
)
{
    const word lawType(dict.get<word>("materialLaw"));

    Info<< "Selecting solid material law " << lawType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown materialLaw " << lawType
            << " in entry 'materialLaw' of " << dict.name() << nl << nl
            << "Valid materialLaw types:" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    return autoPtr<solidMaterialLaw>(cstrIter()(lawType, mesh, dict));
}
