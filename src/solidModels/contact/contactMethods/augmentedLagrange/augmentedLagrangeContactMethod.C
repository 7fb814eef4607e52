/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "augmentedLagrangeContactMethod.H"
#include "addToRunTimeSelectionTable.H"
#include "augmentedLagrangeLaw.H"

namespace Foam
{
namespace contactMethods
{
    defineTypeNameAndDebug(augmentedLagrange, 0);
    addContactMethodToTables(augmentedLagrange);
}
}


// exact once the Uzawa updates have converged
const Foam::contactMethodTraits
Foam::contactMethods::augmentedLagrange::typeTraits
{
    contactMethodTraits::answerKind::exact,
    false,  // openStart
    true,  // allowsSlip
    contactMethodTraits::multiplierKind::augmented,
    true,  // finiteStrain
    "penaltyScale 1; penetrationTolerance 1e-3; multiplierTolerance 1e-6; maxUpdates 100; multiplierUpdate corrector;"
};


Foam::contactMethods::augmentedLagrange::augmentedLagrange
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    uzawaMethod(patch, coeffs)
{}


Foam::scalar Foam::contactMethods::augmentedLagrange::newMultiplier
(
    const contactSlaveState& state,
    const contactSlaveCondition& cond,
    const label facei
) const
{
    if (!cond.active[facei])
    {
        return 0;
    }
    // A face constrained per master face carries the mean of its master
    // faces' shared pressures, not its own law's value: its reaction as
    // lambda left the groups' mean gap at C (lambda_bar - p_j), 3e-8 m
    // with the near-rigid cylinder the slave. The law at the gap the
    // constraint closes has the fixed point where that gap is zero
    return
        state.grouped[facei]
      ? c4f::contact::uzawaUpdate
        (
            lambda()[facei], state.constraintGap[facei], eps(state, facei)
        )
      : state.reaction[facei];
}


void Foam::contactMethods::augmentedLagrange::correct
(
    const contactSlaveState& state,
    contactSlaveCondition& cond
)
{
    const scalarField& lam = lambda();

    cond.nChanged = 0;

    forAll(state.constraintGap, facei)
    {
        const scalar e = eps(state, facei);
        bool active = false;

        if (state.inRange[facei])
        {
            active = staysOrEnters
            (
                state, cond, facei,
                c4f::contact::augmentedLagrangePressure
                (
                    state.constraintGap[facei], lam[facei], e
                ).pressure > 0
            );
        }

        cond.pressure[facei] = carriedPressure(state, cond, facei);
        cond.coupled[facei] = active;
        cond.compliance[facei] = 1/e;
        cond.explicitPressure[facei] = active ? lam[facei] : 0;

        cond.setActive(facei, active);
    }
}
