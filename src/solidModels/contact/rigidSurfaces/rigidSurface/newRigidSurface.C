/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "rigidSurface.H"

Foam::autoPtr<Foam::rigidSurface> Foam::rigidSurface::New
(
    const dictionary& dict,
    const objectRegistry& db
)
{
    const word surfaceType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(surfaceType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown rigid surface type " << surfaceType
            << " in entry 'type' of " << dict.name() << nl << nl
            << "Valid rigid surface types:" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    return autoPtr<rigidSurface>(cstrIter()(dict, db));
}


// ************************************************************************* //
