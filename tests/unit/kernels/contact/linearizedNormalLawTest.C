// Unit tests of the linearization of a normal law into the implicit
// interface law g = C (p0 - p), src/kernels/contact/linearizedNormalLaw.
// The linear law must match the nonlinear one in value and slope at the
// linearization gap, be exact for the laws that are already affine
// (penalty, augmented Lagrange), differ from a nonlinear law only at
// second order, and, re-taken every outer corrector, solve the nonlinear
// law (Newton's method on a scalar spring model).

#include "linearizedNormalLaw.H"
#include "augmentedLagrangeLaw.H"
#include "constitutiveContactLaw.H"
#include "crossConstraintLaw.H"

#include <gtest/gtest.h>
#include <cfloat>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

using namespace c4f::contact;

namespace
{

// The linear law the coupling imposes, solved for the pressure:
// g = C (p0 - p)  =>  p = p0 - g/C
double linearPressure(const LinearizedNormalLaw& l, const double g)
{
    return l.pressure0 - g/l.compliance;
}

// A nonlinear law as a function of g, with a gap where it is curved
struct NamedLaw
{
    const char* name;
    std::function<NormalLawValue(double)> law;
    double curvedGap;
};

const std::vector<NamedLaw> laws
{
    {"constitutive n = 2", [](double g) { return constitutivePressure(g, 1e18, 2.0); }, -1e-6},
    {"constitutive n = 3.33", [](double g) { return constitutivePressure(g, 3e25, 3.33); }, -1e-6},
    {"constitutive n = 0.5", [](double g) { return constitutivePressure(g, 1e9, 0.5); }, -1e-6},
    // Linear on the penetrated side: curved only where open
    {"cross-constraint", [](double g) { return crossConstraintPressure(g, 1e6, 1e12); }, 1e-6}
};

} // End anonymous namespace


TEST(linearizedNormalLaw, penaltyIsItsOwnLinearization)
{
    const double eps = 1e12, gStar = -1e-6;
    const LinearizedNormalLaw l = linearizeNormalLaw(penaltyPressure(gStar, eps), gStar);
    EXPECT_TRUE(l.coupled);
    EXPECT_EQ(l.compliance, 1/eps);
    EXPECT_NEAR(l.pressure0, 0.0, 2*DBL_EPSILON*eps*std::abs(gStar));
    for (const double g : {-1e-3, -2e-6, -1e-9})
    {
        EXPECT_NEAR(linearPressure(l, g), penaltyPressure(g, eps).pressure, 4*DBL_EPSILON*eps*std::abs(g));
    }
}

TEST(linearizedNormalLaw, augmentedLagrangeGivesStoredMultiplier)
{
    // p0 = lambda, C = 1/eps: the form contactMethod names for augmented
    // Lagrange, whatever the gap it is taken at on the active side
    const double lambda = 1e6, eps = 1e12;
    for (const double gStar : {-1e-6, 0.0, 5e-7})
    {
        const LinearizedNormalLaw l =
            linearizeNormalLaw(augmentedLagrangePressure(gStar, lambda, eps), gStar);
        EXPECT_TRUE(l.coupled);
        EXPECT_EQ(l.compliance, 1/eps);
        EXPECT_NEAR(l.pressure0, lambda, 4*DBL_EPSILON*(lambda + eps*std::abs(gStar)));
    }
}

TEST(linearizedNormalLaw, flatLawIsExplicitPressure)
{
    // Open penalty and released augmented Lagrange faces: nothing to couple
    for (const NormalLawValue& v :
        {penaltyPressure(1e-6, 1e12), augmentedLagrangePressure(1e-5, 1e6, 1e12),
         constitutivePressure(1e-6, 1e18, 2.0), crossConstraintPressure(1e-6, 0.0, 1e12)})
    {
        const LinearizedNormalLaw l = linearizeNormalLaw(v, 1e-6);
        EXPECT_FALSE(l.coupled);
        EXPECT_EQ(l.compliance, 0.0);
        EXPECT_EQ(l.pressure0, 0.0);
    }
    // A flat law with a value carries it explicitly
    const LinearizedNormalLaw l = linearizeNormalLaw({5e5, 0.0}, -1e-6);
    EXPECT_FALSE(l.coupled);
    EXPECT_EQ(l.compliance, 0.0);
    EXPECT_EQ(l.pressure0, 5e5);
}

TEST(linearizedNormalLaw, reproducesValueAndSlopeAtLinearizationGap)
{
    for (const auto& [name, law, curvedGap] : laws)
    {
        for (const double gStar : {-1e-4, -1e-6, -1e-8, 1e-7, 1e-6})
        {
            const NormalLawValue v = law(gStar);
            if (!(v.dPressureDGap < 0))
            {
                continue;   // open side of the constitutive law
            }
            const LinearizedNormalLaw l = linearizeNormalLaw(v, gStar);
            ASSERT_TRUE(l.coupled) << name;
            // Value: p0 - g*/C against p, cancellation of p0 and eps_t g*
            const double scale = v.pressure + std::abs(v.dPressureDGap*gStar);
            EXPECT_NEAR(linearPressure(l, gStar), v.pressure, 4*DBL_EPSILON*scale)
                << name << ", g* = " << gStar;
            // Slope -1/C
            EXPECT_NEAR(-1/l.compliance, v.dPressureDGap, 2*DBL_EPSILON*std::abs(v.dPressureDGap))
                << name << ", g* = " << gStar;
            // The coupling's own statement at g*: g* = C (p0 - p(g*))
            EXPECT_NEAR(l.compliance*(l.pressure0 - v.pressure), gStar, 4*DBL_EPSILON*scale*l.compliance)
                << name << ", g* = " << gStar;
        }
    }
}

TEST(linearizedNormalLaw, isTheTangentLineAtAnotherGap)
{
    for (const auto& [name, law, curvedGap] : laws)
    {
        const double gStar = curvedGap;
        const NormalLawValue v = law(gStar);
        const LinearizedNormalLaw l = linearizeNormalLaw(v, gStar);
        ASSERT_TRUE(l.coupled) << name;

        // Another gap: the linear law is p(g*) + p'(g*)(g - g*) ...
        const double dg = 0.2e-6;
        const double g = gStar + dg;
        const double scale = v.pressure + std::abs(v.dPressureDGap)*(std::abs(gStar) + dg);
        EXPECT_NEAR(linearPressure(l, g), v.pressure + v.dPressureDGap*dg, 4*DBL_EPSILON*scale) << name;

        // ... and differs from the law at second order: halving the
        // distance quarters the difference (p'' is smooth near g*)
        const double e1 = law(g).pressure - linearPressure(l, g);
        const double e2 = law(gStar + dg/2).pressure - linearPressure(l, gStar + dg/2);
        EXPECT_NEAR(e1/e2, 4.0, 0.25) << name;
    }
}

TEST(linearizedNormalLaw, retakenEveryCorrectorSolvesNonlinearLaw)
{
    // Outer correctors on the spring g = g0 + p/Kc: each solves the
    // spring with the linear law g = C (p0 - p), i.e.
    //     g = (g0 + p0/Kc)/(1 + 1/(C Kc)),
    // then re-linearizes at the new gap. This is Newton's method on the
    // nonlinear law, so the residual falls quadratically to rounding.
    const double Kc = 2.69e14, g0 = -1e-5;
    for (const auto& [name, law, curvedGap] : laws)
    {
        double g = g0;
        double residual = 1;
        int correctors = 0;
        for (; correctors < 50; ++correctors)
        {
            const LinearizedNormalLaw l = linearizeNormalLaw(law(g), g);
            g = l.coupled
                ? (g0 + l.pressure0/Kc)/(1 + 1/(l.compliance*Kc))
                : g0 + l.pressure0/Kc;
            // Spring and law agree: p_spring(g) = Kc (g - g0) = p(g)
            residual = std::abs(Kc*(g - g0) - law(g).pressure)/(Kc*std::abs(g0));
            if (residual < 1e-12)
            {
                break;
            }
        }
        EXPECT_LT(residual, 1e-12) << name;
        EXPECT_LT(correctors, 30) << name;
    }
}

TEST(linearizedNormalLaw, degenerateSlopes)
{
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();

    // Infinitely stiff: the exact constraint C = 0
    const LinearizedNormalLaw stiff = linearizeNormalLaw({1e6, -inf}, -1e-9);
    EXPECT_TRUE(stiff.coupled);
    EXPECT_EQ(stiff.compliance, 0.0);
    EXPECT_EQ(stiff.pressure0, 1e6);

    // A saturated constitutive slope is still a spring (C = 1/DBL_MAX)
    const LinearizedNormalLaw sat = linearizeNormalLaw({5e19, -DBL_MAX}, -1e-300);
    EXPECT_TRUE(sat.coupled);
    EXPECT_GT(sat.compliance, 0.0);
    EXPECT_TRUE(std::isfinite(sat.pressure0));

    // A slope so small that 1/eps_t overflows, and a NaN slope: explicit
    for (const double slope : {-std::numeric_limits<double>::denorm_min(), nan})
    {
        const LinearizedNormalLaw l = linearizeNormalLaw({3.0, slope}, 1e-6);
        EXPECT_FALSE(l.coupled);
        EXPECT_EQ(l.compliance, 0.0);
        EXPECT_EQ(l.pressure0, 3.0);
    }
}
