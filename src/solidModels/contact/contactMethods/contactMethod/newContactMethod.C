/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactMethod.H"
#include "fvMesh.H"

Foam::autoPtr<Foam::contactMethod> Foam::contactMethod::New
(
    const fvPatch& patch,
    const dictionary& patchDict
)
{
    if (!patchDict.found("method"))
    {
        FatalIOErrorInFunction(patchDict)
            << "Missing entry 'method' in " << patchDict.name()
            << " (slave patch " << patch.name() << ")" << nl
            << "Valid methods:" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    const word methodType(patchDict.get<word>("method"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(methodType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(patchDict)
            << "Unknown method " << methodType
            << " in entry 'method' of " << patchDict.name() << nl << nl
            << "Valid methods:" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    // Finite deformation: only the methods validated under it
    // (contactMethodTraits::finiteStrain)
    const fvMesh& mesh = patch.boundaryMesh().mesh();
    const bool nonlinearGeometry =
        mesh.solutionDict().found("solidMechanics")
     && mesh.solutionDict().subDict("solidMechanics").lookupOrDefault<bool>
        (
            "nonlinearGeometry", false
        );
    if (nonlinearGeometry && !traits(methodType).finiteStrain)
    {
        wordList valid;
        for (const word& m : dictionaryConstructorTablePtr_->sortedToc())
        {
            if (traits(m).finiteStrain)
            {
                valid.append(m);
            }
        }
        FatalIOErrorInFunction(patchDict)
            << "Method " << methodType << " in entry 'method' of "
            << patchDict.name() << " is not available with"
            << " 'nonlinearGeometry yes' in "
            << mesh.solutionDict().subDict("solidMechanics").name()
            << " (not validated under finite deformation: the"
            << " finite-strain patch test). Valid methods there: " << valid
            << exit(FatalIOError);
    }

    const word coeffsName(methodType + "Coeffs");
    // An absent <method>Coeffs is an empty one, named where it would be,
    // so that errors about its entries point at the right place
    dictionary coeffs(patchDict.subOrEmptyDict(coeffsName));

    // The class's defaults under the user's entries: a method reads every
    // optional coefficient with get<>(), its default declared once, in its
    // traits
    for (const entry& e : traits(methodType).defaults())
    {
        if (!coeffs.found(e.keyword(), keyType::LITERAL))
        {
            coeffs.add(e.clone(coeffs).ptr());
        }
    }

    Info<< "Contact patch " << patch.name()
        << ": selecting method " << methodType << endl;

    return autoPtr<contactMethod>(cstrIter()(patch, coeffs));
}
