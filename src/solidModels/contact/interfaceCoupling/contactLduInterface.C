/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactLduInterface.H"

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
