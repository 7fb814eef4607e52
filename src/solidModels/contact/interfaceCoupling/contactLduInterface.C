/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactLduInterface.H"
#include "contactFvMesh.H"

namespace Foam
{
    defineTypeNameAndDebug(contactLduInterface, 0);
}


Foam::tmp<Foam::labelField>
Foam::contactLduInterface::interfaceInternalField
(
    const labelUList& internalData
) const
{
    return tmp<labelField>(new labelField(internalData, faceCells()));
}


Foam::tmp<Foam::labelField>
Foam::contactLduInterface::internalFieldTransfer
(
    const Pstream::commsTypes,
    const labelUList& iF
) const
{
    return interfaceInternalField(iF);
}


Foam::contactLduInterfaceHolder::~contactLduInterfaceHolder()
{
    if (registered_)
    {
        dynamic_cast<const contactFvMesh&>
        (
            contactInterface_.patch().boundaryMesh().mesh()
        ).removeContactInterface
        (
            contactInterface_.patch().index(),
            contactInterface_
        );
    }
}


void Foam::contactLduInterfaceHolder::registerInterface(const word& fieldName)
{
    if (registered_)
    {
        return;
    }

    const fvPatch& patch = contactInterface_.patch();
    const contactFvMesh* mesh =
        dynamic_cast<const contactFvMesh*>(&patch.boundaryMesh().mesh());
    if (!mesh)
    {
        FatalErrorInFunction
            << "Patch " << patch.name() << " of " << fieldName
            << ": the condition solidContact couples the two bodies inside"
            << " the D matrix and needs the solver's mesh type "
            << contactFvMesh::typeName << " (as solidContactFoam creates"
            << " it); this application's mesh is a plain fvMesh"
            << exit(FatalError);
    }
    mesh->addContactInterface(patch.index(), contactInterface_);
    registered_ = true;
}
