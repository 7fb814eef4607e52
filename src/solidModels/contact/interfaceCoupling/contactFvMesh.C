/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactFvMesh.H"
#include "GAMGAgglomeration.H"

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
