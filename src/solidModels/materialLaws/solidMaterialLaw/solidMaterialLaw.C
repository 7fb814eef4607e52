/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "solidMaterialLaw.H"

namespace Foam
{
    defineTypeNameAndDebug(solidMaterialLaw, 0);
    defineRunTimeSelectionTable(solidMaterialLaw, dictionary);
}


Foam::solidMaterialLaw::solidMaterialLaw
(
    const word& lawType,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    mesh_(mesh),
    dict_(dict),
    coeffs_(dict.subDict(lawType + "Coeffs"))
{}


Foam::tmp<Foam::labelField> Foam::solidMaterialLaw::cellMaterials() const
{
    return tmp<labelField>(new labelField(mesh_.nCells(), 0));
}
