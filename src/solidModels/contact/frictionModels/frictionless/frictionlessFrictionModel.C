/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "frictionlessFrictionModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionModels
{
    defineTypeNameAndDebug(frictionless, 0);
    addToRunTimeSelectionTable(frictionModel, frictionless, dictionary);
}
}


Foam::frictionModels::frictionless::frictionless
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    frictionModel(patch, coeffs)
{
    if (coeffs.size())
    {
        FatalIOErrorInFunction(coeffs)
            << "The friction model frictionless has no coefficients, but "
            << coeffs.name() << " has " << coeffs.toc()
            << " (contact patch " << patch.name() << "): remove them, or"
            << " choose stick or coulomb" << exit(FatalIOError);
    }
}


void Foam::frictionModels::frictionless::correct
(
    const contactSlaveState&,
    contactSlaveCondition& cond
)
{
    releaseAll(cond);
}


// ************************************************************************* //
