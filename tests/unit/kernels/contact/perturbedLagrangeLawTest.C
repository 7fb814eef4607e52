// Unit tests of the perturbed Lagrange multiplier step,
// src/kernels/contact/perturbedLagrangeLaw.
// References: Simo, Wriggers & Taylor (1985); Wriggers, Computational
// Contact Mechanics (2nd ed. 2006), ch. 6, chapter eq. 2.31-2.33. On the
// scalar spring model the step is Newton's, so its behaviour (one step
// with the exact stiffness, the contraction factor with an estimate, the
// penalty's fixed point, the Lagrange limit) is derived and asserted.

#include "perturbedLagrangeLaw.H"
#include "normalContactLaws.H"

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
