/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactFvMesh.H"
#include "GAMGAgglomeration.H"
#include "volFields.H"
#include "lduInterfaceField.H"

namespace Foam
{
    defineTypeNameAndDebug(contactFvMesh, 0);
}


Foam::contactFvMesh::contactFvMesh(const IOobject& io)
:
    fvMesh(io),
    contactInterfaces_(boundaryMesh().size(), nullptr)
{}


Foam::lduInterfacePtrsList Foam::contactFvMesh::interfaces() const
{
    lduInterfacePtrsList ifs(fvMesh::interfaces());
    forAll(contactInterfaces_, patchi)
    {
        if (contactInterfaces_[patchi])
        {
            ifs.set(patchi, contactInterfaces_[patchi]);
        }
    }
    return ifs;
}


void Foam::contactFvMesh::addContactInterface
(
    const label patchi,
    const lduInterface& iface
) const
{
    if (contactInterfaces_[patchi] != &iface)
    {
        contactInterfaces_[patchi] = &iface;

        // An agglomeration built without it would not know the interface
        MeshObject<lduMesh, GeometricMeshObject, GAMGAgglomeration>::Delete
        (
            *this
        );
    }
}


void Foam::contactFvMesh::removeContactInterface
(
    const label patchi,
    const lduInterface& iface
) const
{
    if (patchi < contactInterfaces_.size() && contactInterfaces_[patchi] == &iface)
    {
        contactInterfaces_[patchi] = nullptr;
        MeshObject<lduMesh, GeometricMeshObject, GAMGAgglomeration>::Delete
        (
            *this
        );
    }
}


void Foam::contactFvMesh::checkSolverControls(const volVectorField& D) const
{
    // The first contact patch of D: an interface field that OpenFOAM does
    // not couple (processor and cyclic patches are coupled())
    word contactPatch;
    forAll(D.boundaryField(), patchi)
    {
        const fvPatchVectorField& pf = D.boundaryField()[patchi];
        if (isA<lduInterfaceField>(pf) && !pf.coupled())
        {
            contactPatch = pf.patch().name();
            break;
        }
    }
    if (contactPatch.empty())
    {
        return;
    }

    const dictionary& solverControls = solverDict(D.name());
    const auto check = [&](const dictionary& dict)
    {
        if (dict.getOrDefault<Switch>("directSolveCoarsest", false))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'directSolveCoarsest' = true in the solver of "
                << D.name() << " in system/fvSolution (" << dict.name()
                << "): GAMG's direct solve of its coarsest level"
                << " (LUscalarMatrix) takes processor and cyclic interfaces"
                << " only, and " << D.name() << " has the contact interface"
                << " of patch " << contactPatch << ". Valid:"
                << " directSolveCoarsest false (the default: the coarsest"
                << " level solved iteratively), or no such entry"
                << exit(FatalIOError);
        }
        // Processor agglomeration sends the coarse levels' interfaces to
        // other processors by their GAMGInterface type, which has no
        // reader for the contact interface
        if (Pstream::parRun() && dict.found("processorAgglomerator"))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'processorAgglomerator' = "
                << dict.get<word>("processorAgglomerator")
                << " in the solver of " << D.name() << " in system/fvSolution ("
                << dict.name() << "): GAMG's processor agglomeration moves"
                << " the coarse levels' interfaces between processors by"
                << " their type, and cannot move the contact interface of"
                << " patch " << contactPatch << " of " << D.name()
                << ". Valid: no processorAgglomerator entry (each"
                << " processor keeps its own coarse levels)"
                << exit(FatalIOError);
        }
    };
    check(solverControls);
    if (solverControls.isDict("preconditioner"))
    {
        check(solverControls.subDict("preconditioner"));
    }
}
