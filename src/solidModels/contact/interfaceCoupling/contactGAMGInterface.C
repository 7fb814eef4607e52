/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactGAMGInterface.H"
#include "addToRunTimeSelectionTable.H"
#include "ListOps.H"

namespace Foam
{
    defineTypeNameAndDebug(contactGAMGInterface, 0);
    addToRunTimeSelectionTable
    (
        GAMGInterface,
        contactGAMGInterface,
        lduInterface
    );
}


Foam::contactGAMGInterface::contactGAMGInterface
(
    const label index,
    const lduInterfacePtrsList& coarseInterfaces,
    const lduInterface&,
    const labelField& localRestrictAddressing,
    const labelField&,
    const label,
    const label
)
:
    GAMGInterface
    (
        index,
        coarseInterfaces,
        localRestrictAddressing,
        identity(localRestrictAddressing.size())
    )
{}


Foam::tmp<Foam::labelField> Foam::contactGAMGInterface::internalFieldTransfer
(
    const Pstream::commsTypes,
    const labelUList& iF
) const
{
    return interfaceInternalField(iF);
}


void Foam::contactGAMGInterface::write(Ostream& os) const
{
    os  << faceCells_ << token::SPACE << faceRestrictAddressing_;
}
