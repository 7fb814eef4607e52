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


void Foam::solidMaterialLaw::checkGeometry
(
    const bool nonlinearGeometry,
    const dictionary& where
) const
{
    if (needsNonlinearGeometry() && !nonlinearGeometry)
    {
        FatalIOErrorInFunction(where)
            << "materialLaw " << type() << " (" << coeffs_.name()
            << ") is a finite-deformation law, but entry 'nonlinearGeometry'"
            << " in " << where.name() << " is no."
            << " Valid: nonlinearGeometry yes; or, for small strain,"
            << " materialLaw linearElastic"
            << exit(FatalIOError);
    }
}
