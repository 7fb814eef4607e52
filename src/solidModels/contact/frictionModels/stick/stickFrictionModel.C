/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "stickFrictionModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionModels
{
    defineTypeNameAndDebug(stick, 0);
    addToRunTimeSelectionTable(frictionModel, stick, dictionary);
}
}


Foam::frictionModels::stick::stick
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    frictionModel(patch, coeffs)
{
    // Only frictionModel's own entry (closing) is allowed
    wordList unknown;
    for (const word& key : coeffs.toc())
    {
        if (key != "closing")
        {
            unknown.append(key);
        }
    }
    if (unknown.size())
    {
        FatalIOErrorInFunction(coeffs)
            << "The friction model stick has no coefficients (closing"
            << " apart), but " << coeffs.name() << " has " << unknown
            << " (contact patch " << patch.name() << "): remove them, or"
            << " choose coulomb with coulombCoeffs { mu ...; }"
            << exit(FatalIOError);
    }
    addHistory();
}


void Foam::frictionModels::stick::correct
(
    const contactSlaveState& state,
    contactSlaveCondition& cond
)
{
    noteReleases(cond);
    releaseAll(cond);
    forAll(cond.tied, facei)
    {
        if (closing(facei, cond))
        {
            freeClosing(facei, cond);
            continue;
        }
        if (cond.coupled[facei])
        {
            tie(facei, cond);
        }
        setStick(facei, cond.coupled[facei] ? 1 : -1, cond);
        updateSlip(state, cond, facei);
    }
}


// ************************************************************************* //
