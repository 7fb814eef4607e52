/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "perturbedLagrangeContactMethod.H"
#include "addToRunTimeSelectionTable.H"
#include "perturbedLagrangeLaw.H"

namespace Foam
{
namespace contactMethods
{
    defineTypeNameAndDebug(perturbedLagrange, 0);
    addContactMethodToTables(perturbedLagrange);
}
}


// lambda = eps g at the fixed point: the penalty's answer; no slip law
    // for a regularised multiplier (Wriggers 2006, remark 2.7.3)
const Foam::contactMethodTraits
Foam::contactMethods::perturbedLagrange::typeTraits
{
    contactMethodTraits::answerKind::penalty,
    false,  // openStart
    false,  // allowsSlip
    contactMethodTraits::multiplierKind::regularised,
    true,  // finiteStrain
    "penaltyScale 10; constraintTolerance 1e-3; multiplierTolerance 1e-6; maxUpdates 100; multiplierUpdate corrector;"
};


Foam::contactMethods::perturbedLagrange::perturbedLagrange
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    uzawaMethod(patch, coeffs, "constraintTolerance", "|g + lambda/eps|")
{
    // The exact methods' stopping test would be wrong here: at the fixed
    // point the penetration is lambda/eps, not zero
    if (coeffs.found("penetrationTolerance"))
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry 'penetrationTolerance "
            << coeffs.lookup("penetrationTolerance").toString().c_str()
            << "' in " << coeffs.name()
            << " (contact patch " << patch.name() << ") is not an entry of"
            << " perturbedLagrange: its converged penetration is"
            << " lambda/eps (the penalty's), not zero. Use"
            << " constraintTolerance, the tolerance of"
            << " max |g_N + lambda/eps|/h (> 0, default 1e-3)"
            << exit(FatalIOError);
    }
}


Foam::scalar Foam::contactMethods::perturbedLagrange::newMultiplier
(
    const contactSlaveState& state,
    const contactSlaveCondition& cond,
    const label facei
) const
{
    // A coupled face's reaction is the step taken at the gap its solve
    // produced; a free face takes the step at its gap (0 once the inner
    // correctors have converged: a face whose step presses enters)
    return
        cond.coupled[facei]
      ? state.reaction[facei]
      : c4f::contact::perturbedLagrangeUpdate
        (
            lambda()[facei], state.constraintGap[facei], eps(state, facei),
            state.stiffness[facei]
        );
}


Foam::scalar Foam::contactMethods::perturbedLagrange::constraintViolation
(
    const contactSlaveState& state,
    const label facei,
    const scalar lambdaNew
) const
{
    const scalar r = c4f::contact::perturbedLagrangeResidual
    (
        lambdaNew, state.constraintGap[facei], eps(state, facei)
    );

    // A released face (lambda = 0) satisfies the constraint as an
    // inequality: r = -g_N <= 0, its penetration is the violation
    return lambdaNew > 0 ? mag(r) : max(r, scalar(0));
}


void Foam::contactMethods::perturbedLagrange::correct
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
        const scalar Kc = state.stiffness[facei];
        bool active = false;

        if (state.inRange[facei])
        {
            active = staysOrEnters
            (
                state, cond, facei,
                c4f::contact::perturbedLagrangeStepPressure
                (
                    state.constraintGap[facei], lam[facei], e, Kc
                ).pressure > 0
            );
        }

        cond.pressure[facei] = carriedPressure(state, cond, facei);

        // The step's affine law g = C (p0 - p): C = 1/Kc + 1/eps and
        // p0 the step at zero gap (perturbedLagrangeLaw.H)
        cond.coupled[facei] = active;
        cond.compliance[facei] = 1/Kc + 1/e;
        cond.explicitPressure[facei] =
            active
          ? c4f::contact::perturbedLagrangeUpdate(lam[facei], 0, e, Kc)
          : 0;

        cond.setActive(facei, active);
    }
}
