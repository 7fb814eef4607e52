/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "stVenantKirchhoff.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace solidMaterialLaws
{
    defineTypeNameAndDebug(stVenantKirchhoff, 0);
    addToRunTimeSelectionTable(solidMaterialLaw, stVenantKirchhoff, dictionary);
}
}


Foam::solidMaterialLaws::stVenantKirchhoff::stVenantKirchhoff
(
    const word& lawType,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    linearElastic(lawType, mesh, dict)
{}

// ************************************************************************* //
