/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "crossConstraintContactMethod.H"
#include "addToRunTimeSelectionTable.H"
#include "crossConstraintLaw.H"
#include "linearizedNormalLaw.H"

namespace Foam
{
namespace contactMethods
{
    defineTypeNameAndDebug(crossConstraint, 0);
    addContactMethodToTables(crossConstraint);
}
}


// exact once the Uzawa updates have converged
const Foam::contactMethodTraits
Foam::contactMethods::crossConstraint::typeTraits
{
    contactMethodTraits::answerKind::exact,
    false,  // openStart
    true,  // allowsSlip
    contactMethodTraits::multiplierKind::augmented,
    true,  // finiteStrain
    "penaltyScale 1; penetrationTolerance 1e-3; multiplierTolerance 1e-6; maxUpdates 100; multiplierUpdate corrector;"
};


Foam::contactMethods::crossConstraint::crossConstraint
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    uzawaMethod(patch, coeffs)
{}


Foam::scalar Foam::contactMethods::crossConstraint::lawEps
(
    const contactSlaveState& state,
    const label facei
) const
{
    // Capped at four times the two bodies in series: with a slave far
    // stiffer than its master the gap answers with the master's
    // stiffness, and eps from the slave's alone (1000:1) made the open
    // side's decay length lambda/eps 3e-9 m, below what the iterates
    // resolve: the active set cycled for 4768 correctors (63 capped; 98
    // at ten times, 60 at twice). The cap acts where k_s > 3 k_m only:
    // hertzCylinder's like materials (k_s/k_m = 1.31) are unchanged
    return
        eps(state, facei)
       *min(scalar(1), 4*state.pairStiffness[facei]/state.stiffness[facei]);
}


Foam::scalar Foam::contactMethods::crossConstraint::newMultiplier
(
    const contactSlaveState& state,
    const contactSlaveCondition& cond,
    const label facei
) const
{
    const scalar g = state.constraintGap[facei];
    if (cond.coupled[facei])
    {
        // A face constrained per master face carries the mean of its
        // master faces' shared pressures, not its law's value: the law at
        // the gap the constraint closes (as augmentedLagrange's)
        return
            state.grouped[facei]
          ? c4f::contact::crossConstraintPressure
            (
                g, lambda()[facei], lawEps(state, facei)
            ).pressure
          : state.reaction[facei];
    }

    // A free face that penetrates takes none: it enters with the
    // law about lambda = 0 (the penalty), as augmentedLagrange's does. At a
    // converged state no free face penetrates, but in an iterate updated
    // in every corrector it may lie deep (the unconstrained first solve),
    // and the penalty's value as lambda plus the law's own eps (-g) on
    // top pushed the bodies apart, then let them through, in turn
    return
        g > 0
      ? c4f::contact::crossConstraintPressure
        (
            g, lambda()[facei], lawEps(state, facei)
        ).pressure
      : 0;
}


void Foam::contactMethods::crossConstraint::correct
(
    const contactSlaveState& state,
    contactSlaveCondition& cond
)
{
    // Below this fraction of its multiplier an open face's exponential
    // pressure is released (and the face counts as out of contact)
    const scalar release = 1e-12;

    const scalarField& lam = lambda();

    cond.nChanged = 0;

    forAll(state.constraintGap, facei)
    {
        const scalar g = state.constraintGap[facei];
        const scalar e = lawEps(state, facei);
        const scalar l = lam[facei];

        cond.pressure[facei] =
            state.inRange[facei] && (cond.coupled[facei] || cond.active[facei])
          ? state.reaction[facei]
          : 0;
        cond.clearLaw(facei);

        bool active = false;
        if (state.inRange[facei])
        {
            if (l > 0)
            {
                const c4f::contact::NormalLawValue v =
                    c4f::contact::crossConstraintPressure(g, l, e);
                const c4f::contact::LinearizedNormalLaw lin =
                    c4f::contact::linearizeNormalLaw(v, g);

                active = cond.decide(facei, v.pressure > release*l);
                if (active && lin.coupled)
                {
                    cond.coupled[facei] = true;
                    cond.compliance[facei] = lin.compliance;
                    cond.explicitPressure[facei] = lin.pressure0;
                }
                else if (active)
                {
                    cond.explicitPressure[facei] = v.pressure;
                }
            }
            else
            {
                // The penalty law eps <-g_N>, with the penalty's active set
                active = staysOrEnters(state, cond, facei, g < 0);
                cond.coupled[facei] = active;
                cond.compliance[facei] = 1/e;
            }
        }

        cond.setActive(facei, active);
    }
}
