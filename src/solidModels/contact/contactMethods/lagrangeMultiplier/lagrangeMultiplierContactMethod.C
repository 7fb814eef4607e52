/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "lagrangeMultiplierContactMethod.H"
#include "addToRunTimeSelectionTable.H"
#include "normalContactLaws.H"

namespace Foam
{
namespace contactMethods
{
    defineTypeNameAndDebug(lagrangeMultiplier, 0);
    addContactMethodToTables(lagrangeMultiplier);
}
}


// exact: the gap closes; active set from the primal-dual rule
const Foam::contactMethodTraits
Foam::contactMethods::lagrangeMultiplier::typeTraits
{
    contactMethodTraits::answerKind::exact,
    false,  // openStart
    true,  // allowsSlip
    contactMethodTraits::multiplierKind::none,
    true,  // finiteStrain
    "activeSetScale 1;"
};


Foam::contactMethods::lagrangeMultiplier::lagrangeMultiplier
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    contactMethod(patch, coeffs),
    activeSetScale_(coeffs.get<scalar>("activeSetScale"))
{
    if (!c4f::contact::validPenalty(activeSetScale_))
    {
        FatalIOErrorInFunction(coeffs)
            << "Invalid activeSetScale " << activeSetScale_ << " in "
            << coeffs.name() << " (contact patch " << patch.name() << "): "
            << c4f::contact::describePenaltyRequirement().c_str()
            << exit(FatalIOError);
    }
}


void Foam::contactMethods::lagrangeMultiplier::correct
(
    const contactSlaveState& state,
    contactSlaveCondition& cond
)
{
    cond.nChanged = 0;

    forAll(state.constraintGap, facei)
    {
        // An inactive face was traction-free: its multiplier is zero, not
        // the solver-tolerance residue of its reaction
        const scalar lambda =
            cond.active[facei] ? state.reaction[facei] : 0;

        const scalar c = activeSetScale_*state.pairStiffness[facei];

        const bool active = cond.decide
        (
            facei,
            state.inRange[facei]
         && c4f::contact::activeByPrimalDual
            (
                lambda, state.constraintGap[facei], c
            )
        );

        cond.setActive(facei, active);

        cond.coupled[facei] = active;
        cond.compliance[facei] = 0;
        cond.explicitPressure[facei] = 0;
        cond.pressure[facei] = lambda;
    }
}
