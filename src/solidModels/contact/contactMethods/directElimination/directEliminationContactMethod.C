/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "directEliminationContactMethod.H"
#include "addToRunTimeSelectionTable.H"
#include "directEliminationLaw.H"

namespace Foam
{
namespace contactMethods
{
    defineTypeNameAndDebug(directElimination, 0);
    addContactMethodToTables(directElimination);
}
}


// exact, no multiplier; no coefficients
const Foam::contactMethodTraits
Foam::contactMethods::directElimination::typeTraits
{
    contactMethodTraits::answerKind::exact,
    false,  // openStart
    true,  // allowsSlip
    contactMethodTraits::multiplierKind::none,
    true,  // finiteStrain
    ""
};


Foam::contactMethods::directElimination::directElimination
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    contactMethod(patch, coeffs)
{
    // An entry here would be silently ignored: the constraint is exact
    // and the active set has no constant (activeSetScale is the Lagrange
    // multiplier's, penaltyScale the penalty family's)
    if (!coeffs.empty())
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry '" << coeffs.toc()[0] << "' in " << coeffs.name()
            << " (contact patch " << patch.name() << "): directElimination"
            << " has no coefficients (g_N = 0 is imposed exactly, a face"
            << " enters when g_N < 0 and leaves when its reaction turns"
            << " tensile); remove the entries " << coeffs.toc()
            << exit(FatalIOError);
    }
}


void Foam::contactMethods::directElimination::correct
(
    const contactSlaveState& state,
    contactSlaveCondition& cond
)
{
    cond.nChanged = 0;

    forAll(state.constraintGap, facei)
    {
        const bool active = cond.decide
        (
            facei,
            state.inRange[facei]
         && c4f::contact::directEliminationActive
            (
                cond.active[facei],
                state.reaction[facei],
                state.constraintGap[facei]
            )
        );

        cond.pressure[facei] = carriedPressure(state, cond, facei);
        cond.setActive(facei, active);
        cond.coupled[facei] = active;
        cond.compliance[facei] = 0;
        cond.explicitPressure[facei] = 0;
    }
}
