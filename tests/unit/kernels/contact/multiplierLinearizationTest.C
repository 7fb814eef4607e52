// Unit tests of the multiplier linearisation of the normal laws:
// dp_N/dlambda_N of the laws about a stored multiplier (augmented Lagrange,
// cross-constraint, the perturbed Lagrange step) and the primal-dual
// complementarity function of the exact constraint with its generalised
// derivative (src/kernels/contact/normalContactLaws, augmentedLagrangeLaw,
// crossConstraintLaw, perturbedLagrangeLaw). References: Wriggers,
// Computational Contact Mechanics (2nd ed. 2006), sec. 6.3 and 6.5;
// Hintermueller, Ito & Kunisch (2002) for the semi-smooth Newton step.
// Every derivative is checked against central differences on sweeps that
// stay a step away from the laws' kinks, and the complementarity function
// by what it must do: vanish exactly on the contact conditions and give a
// Newton iteration that ends in finitely many steps.

#include "augmentedLagrangeLaw.H"
#include "crossConstraintLaw.H"
#include "perturbedLagrangeLaw.H"
#include "constitutiveContactLaw.H"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

using namespace c4f::contact;

namespace
{

// Steel over a 1 mm cell: the stiffness K/h a face sees [Pa/m]
const double Kc = 2.69e14;

// Central difference of f at x with a step relative to the scale s
double central(const std::function<double(double)>& f, double x, double s)
{
    const double h = 1e-6*s;
    return (f(x + h) - f(x - h))/(2*h);
}

// Gaps [m] and multipliers [Pa] of the sweeps: penetrating and open
const std::vector<double> gaps{-3e-6, -1e-7, 2e-8, 4e-7, 5e-6};
const std::vector<double> lambdas{1e6, 3e8, 2e9};

} // End anonymous namespace


TEST(MultiplierLinearization, AugmentedLagrangeAgainstCentralDifferences)
{
    const double eps = 0.1*Kc;
    for (const double g : gaps)
    {
        for (const double l : lambdas)
        {
            // A step from the kink lambda = eps g
            if (std::abs(l - eps*g) < 1e-3*l)
            {
                continue;
            }
            const NormalLawValue v = augmentedLagrangePressure(g, l, eps);
            const double fd = central
            (
                [&](double x) { return augmentedLagrangePressure(g, x, eps).pressure; },
                l, l
            );
            EXPECT_NEAR(v.dPressureDMultiplier, fd, 1e-6) << "g " << g << " lambda " << l;
            const double fdg = central
            (
                [&](double x) { return augmentedLagrangePressure(x, l, eps).pressure; },
                g, 1e-6
            );
            EXPECT_NEAR(v.dPressureDGap, fdg, 1e-6*eps) << "g " << g << " lambda " << l;
        }
    }
}


TEST(MultiplierLinearization, CrossConstraintAgainstCentralDifferences)
{
    const double eps = 0.1*Kc;
    for (const double g : gaps)
    {
        for (const double l : lambdas)
        {
            const NormalLawValue v = crossConstraintPressure(g, l, eps);
            const double fd = central
            (
                [&](double x) { return crossConstraintPressure(g, x, eps).pressure; },
                l, l
            );
            // The open branch's slope e^-x (1 + x) is at most 1
            EXPECT_NEAR(v.dPressureDMultiplier, fd, 1e-6) << "g " << g << " lambda " << l;
            EXPECT_GE(v.dPressureDMultiplier, 0.0);
            EXPECT_LE(v.dPressureDMultiplier, 1.0 + 1e-12);
        }
    }
    // No multiplier (lambda <= 0): the penalty law, which does not depend
    // on it
    EXPECT_EQ(crossConstraintPressure(-1e-6, 0.0, eps).dPressureDMultiplier, 0.0);
}


TEST(MultiplierLinearization, PerturbedLagrangeStepAgainstCentralDifferences)
{
    for (const double epsScale : {0.01, 1.0, 100.0})
    {
        const double eps = epsScale*Kc;
        for (const double g : gaps)
        {
            for (const double l : lambdas)
            {
                const NormalLawValue v = perturbedLagrangeStepPressure(g, l, eps, Kc);
                if (v.pressure <= 1e-3*l)
                {
                    // Released (or at the kink): no slope
                    if (v.pressure == 0)
                    {
                        EXPECT_EQ(v.dPressureDMultiplier, 0.0);
                    }
                    continue;
                }
                const double fd = central
                (
                    [&](double x)
                    {
                        return perturbedLagrangeStepPressure(g, x, eps, Kc).pressure;
                    },
                    l, l
                );
                EXPECT_NEAR(v.dPressureDMultiplier, fd, 1e-6)
                    << "eps/Kc " << epsScale << " g " << g << " lambda " << l;
            }
        }
    }
    // The exact limit eps -> infinity: the multiplier carries over whole
    // less what the stiffness takes, k/Kc -> 1
    const NormalLawValue exact =
        perturbedLagrangeStepPressure(-1e-6, 1e9, HUGE_VAL, Kc);
    EXPECT_NEAR(exact.dPressureDMultiplier, 1.0, 1e-12);
}


TEST(MultiplierLinearization, LawsWithoutMultiplierHaveNone)
{
    EXPECT_EQ(penaltyPressure(-1e-6, Kc).dPressureDMultiplier, 0.0);
    EXPECT_EQ(constitutivePressure(-1e-6, 1e20, 2.0).dPressureDMultiplier, 0.0);
}


TEST(PrimalDualComplementarity, VanishesExactlyOnTheContactConditions)
{
    const double c = Kc;
    // lambda >= 0, g >= 0, lambda g = 0: C = 0
    EXPECT_EQ(primalDualComplementarity(0.0, 1e-6, c).value, 0.0);
    EXPECT_EQ(primalDualComplementarity(1e9, 0.0, c).value, 0.0);
    EXPECT_EQ(primalDualComplementarity(0.0, 0.0, c).value, 0.0);
    // Violations: penetration, tension, both nonzero
    EXPECT_NE(primalDualComplementarity(0.0, -1e-6, c).value, 0.0);
    EXPECT_NE(primalDualComplementarity(-1e8, 1e-6, c).value, 0.0);
    EXPECT_NE(primalDualComplementarity(1e9, 1e-6, c).value, 0.0);
}


TEST(PrimalDualComplementarity, GeneralisedDerivativeAndActiveSide)
{
    const double c = Kc;
    for (const double g : gaps)
    {
        for (const double l : {-1e8, 0.0, 1e6, 3e8, 2e9})
        {
            const ComplementarityValue v = primalDualComplementarity(l, g, c);
            const bool active = activeByPrimalDual(l, g, c);
            EXPECT_EQ(v.dValueDMultiplier, active ? 0.0 : 1.0);
            EXPECT_EQ(v.dValueDGap, active ? c : 0.0);
            // Away from the kink the generalised derivative is the
            // derivative
            if (std::abs(l - c*g) > 1e-3*(std::abs(l) + std::abs(c*g)))
            {
                const double fdl = central
                (
                    [&](double x) { return primalDualComplementarity(x, g, c).value; },
                    l, std::abs(l) + 1e6
                );
                const double fdg = central
                (
                    [&](double x) { return primalDualComplementarity(l, x, c).value; },
                    g, 1e-9
                );
                EXPECT_NEAR(v.dValueDMultiplier, fdl, 1e-6);
                EXPECT_NEAR(v.dValueDGap, fdg, 1e-6*c);
            }
        }
    }
}


// A face on a spring: the gap under a pressure lambda is g = g0 + lambda/Kc.
// Semi-smooth Newton on C(lambda, g(lambda)) = 0 with the generalised
// derivative ends, from any start, at the exact answer in at most two
// steps (one to pick the side, one on it): the property the semi-smooth
// Newton-Krylov loop relies on.
TEST(PrimalDualComplementarity, SemiSmoothNewtonEndsInTwoSteps)
{
    const double c = Kc;
    for (const double g0 : {-2e-6, 3e-6})
    {
        const double exact = g0 < 0 ? -g0*Kc : 0.0;
        for (const double start : {0.0, 1e7, 5e9, -1e9})
        {
            double l = start;
            int steps = 0;
            for (; steps < 10; ++steps)
            {
                const double g = g0 + l/Kc;
                const ComplementarityValue v = primalDualComplementarity(l, g, c);
                if (std::abs(v.value) <= 1e-12*(std::abs(exact) + 1))
                {
                    break;
                }
                const double J = v.dValueDMultiplier + v.dValueDGap/Kc;
                l -= v.value/J;
            }
            EXPECT_LE(steps, 2) << "g0 " << g0 << " start " << start;
            EXPECT_NEAR(l, exact, 1e-9*(exact + 1)) << "g0 " << g0 << " start " << start;
        }
    }
}
