// Unit tests of the perturbed Lagrange multiplier step,
// src/kernels/contact/perturbedLagrangeLaw.
// References: Simo, Wriggers & Taylor (1985); Wriggers, Computational
// Contact Mechanics (2nd ed. 2006), ch. 6, chapter eq. 2.31-2.33. On the
// scalar spring model the step is Newton's, so its behaviour (one step
// with the exact stiffness, the contraction factor with an estimate, the
// penalty's fixed point, the Lagrange limit) is derived and asserted.
// The step as a law of the gap (perturbedLagrangeStepPressure, what the
// solver holds implicitly): its slope against central differences, its
// linearisation, and the implicit step's contraction
// (1/Kc)/(1/Kc + 1/eps + 1/Kt) for any true stiffness Kt, including
// those where the explicit step diverges.

#include "perturbedLagrangeLaw.H"
#include "normalContactLaws.H"
#include "linearizedNormalLaw.H"

#include <gtest/gtest.h>
#include <cfenv>
#include <cmath>
#include <limits>
#include <vector>

using namespace c4f::contact;

namespace
{

// Steel over a 1 mm cell, and the prescribed interference of the model
// problem: a spring of stiffness Kc pressed so that g = g0 + lambda/Kc
const double Kc = 2.69e14;
const double g0 = -1e-5;

double gapOf(const double lambda, const double g00 = g0)
{
    return g00 + lambda/Kc;
}

// The penalty answer on the model problem: p = eps (-g0 - p/Kc)
double penaltyAnswer(const double eps)
{
    return eps*Kc*(-g0)/(Kc + eps);
}

} // End anonymous namespace


TEST(perturbedLagrangeLaw, residualAndStep)
{
    const double eps = 1e12, K = 4e12;
    EXPECT_DOUBLE_EQ(perturbedLagrangeResidual(1e6, -2e-6, eps), 1e-6);
    EXPECT_DOUBLE_EQ(perturbedLagrangeResidual(0.0, 3e-6, eps), -3e-6);
    // 1e6 + 1e-6/(0.25e-12 + 1e-12)
    EXPECT_DOUBLE_EQ(perturbedLagrangeUpdate(1e6, -2e-6, eps, K), 1.8e6);
}

TEST(perturbedLagrangeLaw, cannotPull)
{
    const double eps = 1e12;
    // An open face with no multiplier stays released; a pressed face that
    // opens far enough is released in one step rather than pulling
    EXPECT_EQ(perturbedLagrangeUpdate(0.0, 1e-6, eps, Kc), 0.0);
    EXPECT_EQ(perturbedLagrangeUpdate(1e6, 1e-3, eps, Kc), 0.0);
    EXPECT_EQ(perturbedLagrangeUpdate(-5.0, 1e-6, eps, Kc), 0.0);
}

TEST(perturbedLagrangeLaw, fixedPointIsPenaltyPressure)
{
    // At any gap, lambda = eps <-g> is left unchanged
    for (const double eps : {1e9, 1e12, 2.69e14, 1e16})
    {
        for (const double g : {-1e-3, -1e-6, -1e-9, 0.0, 1e-9, 1e-6})
        {
            const double lambda = penaltyPressure(g, eps).pressure;
            EXPECT_NEAR(perturbedLagrangeUpdate(lambda, g, eps, Kc), lambda, 1e-14*std::abs(lambda))
                << "eps = " << eps << ", g = " << g;
        }
    }
}

// With g(lambda) = g0 + lambda/Kc the residual is
//     r(lambda) = -g0 - lambda (1/Kc + 1/eps),
// linear with slope -D, D = 1/Kc + 1/eps. The step with an estimate Ke,
// lambda + r/De (De = 1/Ke + 1/eps), gives the error
//     e' = e (1 - D/De);
// with Ke = Kc this is 0: one step to lambda = -g0/D, the penalty answer.
TEST(perturbedLagrangeLaw, exactStiffnessConvergesInOneStep)
{
    for (const double scale : {0.1, 1.0, 10.0})
    {
        const double eps = scale*Kc;
        const double lambda1 = perturbedLagrangeUpdate(0.0, gapOf(0.0), eps, Kc);
        EXPECT_NEAR(lambda1, penaltyAnswer(eps), 1e-13*penaltyAnswer(eps)) << scale;
        // It is the penalty law at its own gap, and the constraint holds
        EXPECT_NEAR(lambda1, penaltyPressure(gapOf(lambda1), eps).pressure, 1e-12*lambda1);
        EXPECT_NEAR(perturbedLagrangeResidual(lambda1, gapOf(lambda1), eps), 0.0, 1e-12*std::abs(g0));
        // A second step changes nothing
        const double lambda2 = perturbedLagrangeUpdate(lambda1, gapOf(lambda1), eps, Kc);
        EXPECT_NEAR(lambda2, lambda1, 1e-14*lambda1);
    }
}

TEST(perturbedLagrangeLaw, estimatedStiffnessConvergesGeometrically)
{
    // Under-estimates converge monotonically, over-estimates (factor
    // 1.5 here) by alternating overshoot, both at the rate 1 - D/De
    for (const double scale : {0.1, 1.0, 10.0})
    {
        for (const double estimate : {0.2, 0.5, 1.5})
        {
            const double eps = scale*Kc, Ke = estimate*Kc;
            const double D = 1/Kc + 1/eps, De = 1/Ke + 1/eps;
            const double rate = 1 - D/De;
            const double target = penaltyAnswer(eps);
            double lambda = 0;
            int steps = 0;
            while (std::abs(lambda - target) > 1e-6*target && steps < 500)
            {
                const double next = perturbedLagrangeUpdate(lambda, gapOf(lambda), eps, Ke);
                EXPECT_NEAR((next - target)/(lambda - target), rate, 1e-6)
                    << "eps/Kc = " << scale << ", Ke/Kc = " << estimate << ", step " << steps;
                lambda = next;
                ++steps;
            }
            EXPECT_LT(steps, 500);
        }
    }
}

TEST(perturbedLagrangeLaw, tendsToLagrangeMultiplierAsEpsGrows)
{
    // The exact multiplier of the model problem closes the gap
    const double lambdaStar = -Kc*g0;
    for (const double scale : {1e2, 1e4, 1e6})
    {
        const double eps = scale*Kc;
        const double lambda = perturbedLagrangeUpdate(0.0, gapOf(0.0), eps, Kc);
        // lambda/lambda* = eps/(Kc + eps): off by about 1/scale
        EXPECT_NEAR(lambda/lambdaStar, 1.0, 1.01/scale) << scale;
        EXPECT_GT(lambda/lambdaStar, 1.0 - 1.0/scale) << scale;
    }

    // eps = infinity is the Lagrange multiplier itself: one Newton step
    // lambda + Kc (-g) and a closed gap
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(perturbedLagrangeResidual(1e6, -2e-6, inf), 2e-6);
    const double lambda = perturbedLagrangeUpdate(0.0, gapOf(0.0), inf, Kc);
    EXPECT_NEAR(lambda, lambdaStar, 1e-14*lambdaStar);
    EXPECT_NEAR(gapOf(lambda), 0.0, 1e-14*std::abs(g0));
}

TEST(perturbedLagrangeLaw, openModelProblemReleases)
{
    // A spring that does not reach: the multiplier goes to 0 in one step
    // from any start and stays
    const double gOpen = 1e-5, eps = Kc;
    for (const double start : {0.0, 1e3, 1e9})
    {
        const double lambda1 = perturbedLagrangeUpdate(start, gapOf(start, gOpen), eps, Kc);
        EXPECT_EQ(lambda1, 0.0) << start;
        EXPECT_EQ(perturbedLagrangeUpdate(lambda1, gapOf(lambda1, gOpen), eps, Kc), 0.0);
    }
}

TEST(perturbedLagrangeLaw, degenerateInputsStayFinite)
{
    std::vector<double> values;
    std::feclearexcept(FE_ALL_EXCEPT);
    for (const double eps : {1e-200, 1.0, 1e12, 1e200, std::numeric_limits<double>::infinity()})
    {
        for (const double K : {1e-200, 1.0, 2.69e14, 1e200})
        {
            for (const double lambda : {-1e6, 0.0, 1e-300, 1e6, 1e12})
            {
                for (const double g : {-1e3, -1.0, -1e-300, -0.0, 0.0, 1e-300, 1.0, 1e3})
                {
                    values.push_back(perturbedLagrangeUpdate(lambda, g, eps, K));
                    values.push_back(perturbedLagrangeResidual(lambda, g, eps));
                }
            }
        }
    }
    const int raised = std::fetestexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
    EXPECT_EQ(raised, 0);
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        EXPECT_TRUE(std::isfinite(values[i])) << i;
        if (i % 2 == 0)
        {
            EXPECT_GE(values[i], 0.0) << i;
        }
    }
}


// The step as a law of the gap (perturbedLagrangeStepPressure), the form
// in which the solver takes it implicitly

TEST(perturbedLagrangeStep, isTheUpdateWithItsSlope)
{
    for (const double scale : {0.1, 1.0, 10.0, 1e3})
    {
        const double eps = scale*Kc, D = 1/Kc + 1/eps;
        for (const double lambda : {0.0, 1e3, 1e6, 1e9})
        {
            for (const double g : {-1e-3, -1e-6, -1e-9, 0.0, 1e-9, 1e-6, 1e-3})
            {
                const NormalLawValue v = perturbedLagrangeStepPressure(g, lambda, eps, Kc);
                const double p = perturbedLagrangeUpdate(lambda, g, eps, Kc);
                EXPECT_EQ(v.pressure, p);
                EXPECT_EQ(v.dPressureDGap, p > 0 ? -1/D : 0.0)
                    << "eps/Kc = " << scale << ", lambda = " << lambda << ", g = " << g;
            }
        }
    }
}

TEST(perturbedLagrangeStep, derivativeMatchesCentralDifferencesAwayFromRelease)
{
    for (const double scale : {0.1, 1.0, 10.0, 1e3})
    {
        const double eps = scale*Kc;
        for (const double lambda : {0.0, 1e6, 1e9})
        {
            // The step reaches 0 at the release gap g_r = lambda/Kc
            const double gr = lambda/Kc;
            for (const double g : {-1e-4, -1e-6, -1e-8, 1e-8, 1e-6, 1e-4})
            {
                const double h = 1e-6*std::abs(g);
                // Skip gaps within two steps of the kink
                if (std::abs(g - gr) < 4*h)
                {
                    continue;
                }
                const double fd =
                    (
                        perturbedLagrangeStepPressure(g + h, lambda, eps, Kc).pressure
                      - perturbedLagrangeStepPressure(g - h, lambda, eps, Kc).pressure
                    )/(2*h);
                const double slope =
                    perturbedLagrangeStepPressure(g, lambda, eps, Kc).dPressureDGap;
                EXPECT_NEAR(fd, slope, 1e-6*std::abs(1/(1/Kc + 1/eps)))
                    << "eps/Kc = " << scale << ", lambda = " << lambda << ", g = " << g;
            }
        }
    }
}

TEST(perturbedLagrangeStep, exactlyAtReleaseIsInactive)
{
    // lambda + (-g - lambda/eps)/(1/Kc + 1/eps) = 0 at g = lambda/Kc; with
    // lambda = 0 that is g = 0, exactly representable
    const NormalLawValue v = perturbedLagrangeStepPressure(0.0, 0.0, Kc, Kc);
    EXPECT_EQ(v.pressure, 0.0);
    EXPECT_EQ(v.dPressureDGap, 0.0);
    // Just inside it presses, with the full slope
    const NormalLawValue w = perturbedLagrangeStepPressure(-1e-300, 0.0, Kc, Kc);
    EXPECT_GT(w.pressure, 0.0);
    EXPECT_DOUBLE_EQ(w.dPressureDGap, -0.5*Kc);
}

TEST(perturbedLagrangeStep, linearizedIsSpringAboutScaledMultiplier)
{
    // The interface takes it as g = C (p0 - p): C = 1/Kc + 1/eps and
    // p0 = lambda (1/Kc)/(1/Kc + 1/eps), the step at zero gap, from
    // wherever on the active side it is linearised
    for (const double scale : {0.1, 1.0, 10.0})
    {
        const double eps = scale*Kc, C = 1/Kc + 1/eps;
        const double lambda = 3e6;
        const double p0 = perturbedLagrangeUpdate(lambda, 0.0, eps, Kc);
        EXPECT_NEAR(p0, lambda*(1/Kc)/C, 1e-14*lambda);
        for (const double g : {-1e-6, -1e-9, 0.0, 1e-9})
        {
            const LinearizedNormalLaw lin =
                linearizeNormalLaw(perturbedLagrangeStepPressure(g, lambda, eps, Kc), g);
            EXPECT_TRUE(lin.coupled);
            EXPECT_NEAR(lin.compliance, C, 1e-14*C) << scale << " " << g;
            EXPECT_NEAR(lin.pressure0, p0, 1e-9*p0) << scale << " " << g;
        }
    }
}

// The implicit step on the spring model with a true stiffness Kt that the
// estimate Kc need not match: g = g0 + p/Kt, and the step's law held
// inside the solve, p = p0 + (-g)/C, gives
//     p (1 + 1/(Kt C)) = p0 + (-g0)/C,   p0 = lambda (1/Kc)/C,
// so the error of lambda <- p contracts by (1/Kc)/(C + 1/Kt) =
// (1/Kc)/(1/Kc + 1/eps + 1/Kt), for any Kt, Kc, eps > 0.
TEST(perturbedLagrangeStep, implicitStepConvergesForAnyEstimate)
{
    for (const double scale : {1.0, 10.0, 1e3})
    {
        // Kt/Kc: 0.05 is a face whose gap answers 20 times softer than
        // K/h (a uniform load on a column 20 cells high), where the
        // explicit step diverges
        for (const double ratio : {0.05, 0.5, 1.0, 2.0})
        {
            const double eps = scale*Kc, Kt = ratio*Kc;
            const double target = eps*Kt*(-g0)/(Kt + eps);
            const double rate = (1/Kc)/(1/Kc + 1/eps + 1/Kt);
            const double explicitRate = 1 - (1/Kt + 1/eps)/(1/Kc + 1/eps);
            if (ratio < 0.5)
            {
                EXPECT_GT(std::abs(explicitRate), 1.0) << scale << " " << ratio;
            }
            double lambda = 0;
            int steps = 0;
            while (std::abs(lambda - target) > 1e-9*target && steps < 200)
            {
                // The inner solve: Newton on p = P(g0 + p/Kt; lambda), one
                // step on the affine branch
                double p = lambda;
                for (int it = 0; it < 5; ++it)
                {
                    const NormalLawValue v =
                        perturbedLagrangeStepPressure(g0 + p/Kt, lambda, eps, Kc);
                    p -= (p - v.pressure)/(1 - v.dPressureDGap/Kt);
                }
                if (lambda > 0)
                {
                    EXPECT_NEAR((p - target)/(lambda - target), rate, 1e-6)
                        << "eps/Kc = " << scale << ", Kt/Kc = " << ratio << ", step " << steps;
                }
                lambda = p;
                ++steps;
            }
            EXPECT_LT(steps, 200) << scale << " " << ratio;
            // The fixed point: the penalty's answer, the perturbed
            // constraint satisfied
            EXPECT_NEAR
            (
                perturbedLagrangeResidual(lambda, g0 + lambda/Kt, eps), 0.0,
                1e-8*std::abs(g0)
            );
        }
    }
}

TEST(perturbedLagrangeStep, degenerateInputsStayFinite)
{
    std::feclearexcept(FE_ALL_EXCEPT);
    std::vector<NormalLawValue> values;
    for (const double eps : {1e-200, 1.0, 1e12, 1e200, std::numeric_limits<double>::infinity()})
    {
        for (const double K : {1e-200, 1.0, 2.69e14, 1e200})
        {
            for (const double lambda : {-1e6, 0.0, 1e-300, 1e6, 1e12})
            {
                for (const double g : {-1e3, -1.0, -1e-300, -0.0, 0.0, 1e-300, 1.0, 1e3})
                {
                    values.push_back(perturbedLagrangeStepPressure(g, lambda, eps, K));
                }
            }
        }
    }
    EXPECT_EQ(std::fetestexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW), 0);
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        EXPECT_TRUE(std::isfinite(values[i].pressure)) << i;
        EXPECT_TRUE(std::isfinite(values[i].dPressureDGap)) << i;
        EXPECT_GE(values[i].pressure, 0.0) << i;
        EXPECT_LE(values[i].dPressureDGap, 0.0) << i;
    }
}
