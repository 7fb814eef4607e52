/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "mechanicalModel.H"
#include "fvMesh.H"
#include "Time.H"

namespace Foam
{
    defineTypeNameAndDebug(mechanicalModel, 0);
}

const Foam::word Foam::mechanicalModel::dictName("mechanicalProperties");


Foam::mechanicalModel::mechanicalModel(const fvMesh& mesh)
:
    IOdictionary
    (
        IOobject
        (
            dictName,
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ_IF_MODIFIED,
            IOobject::NO_WRITE,
            true
        )
    ),
    law_(solidMaterialLaw::New(mesh, *this))
{}


const Foam::mechanicalModel& Foam::mechanicalModel::New(const fvMesh& mesh)
{
    if (!mesh.foundObject<mechanicalModel>(dictName))
    {
        mechanicalModel* ptr = new mechanicalModel(mesh);
        ptr->store();
    }
    return mesh.lookupObject<mechanicalModel>(dictName);
}
