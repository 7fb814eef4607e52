// Unit tests of the penalty and Lagrange-multiplier normal laws,
// src/kernels/contact/normalContactLaws.

#include "normalContactLaws.H"

#include <gtest/gtest.h>
#include <cmath>
#include <limits>

using namespace c4f::contact;

TEST(penaltyLaw, pressureIsPenaltyTimesPenetration)
{
    const double eps = 2e12;
    EXPECT_DOUBLE_EQ(penaltyPressure(-1e-6, eps).pressure, 2e6);
    EXPECT_DOUBLE_EQ(penaltyPressure(1e-6, eps).pressure, 0.0);
    EXPECT_DOUBLE_EQ(penaltyPressure(0.0, eps).pressure, 0.0);
}

TEST(penaltyLaw, derivativeMatchesCentralDifferencesAwayFromZero)
{
    const double eps = 3.7e9, h = 1e-9;
    for (const double g : {-1e-3, -1e-5, 1e-5, 1e-3})
    {
        const double fd =
            (penaltyPressure(g + h, eps).pressure - penaltyPressure(g - h, eps).pressure)/(2*h);
        EXPECT_NEAR(penaltyPressure(g, eps).dPressureDGap, fd, 1e-6*eps);
    }
}

TEST(penaltyLaw, stiffnessScaledDefault)
{
    // s K / h with K = 2mu + lambda of steel and h = 1 mm
    EXPECT_NEAR(stiffnessScaledPenalty(5.0, 2.69e11, 1e-3), 1.345e15, 1e3);
}

TEST(penaltyLaw, validation)
{
    EXPECT_TRUE(validPenalty(1.0));
    EXPECT_FALSE(validPenalty(0.0));
    EXPECT_FALSE(validPenalty(-1.0));
    EXPECT_FALSE(validPenalty(std::numeric_limits<double>::quiet_NaN()));
    EXPECT_FALSE(validPenalty(std::numeric_limits<double>::infinity()));
}

TEST(lagrangeMultiplier, primalDualRule)
{
    const double c = 1e14;
    EXPECT_TRUE(activeByPrimalDual(1e6, 0.0, c));     // pressed, closed
    EXPECT_TRUE(activeByPrimalDual(0.0, -1e-9, c));   // penetrating
    EXPECT_FALSE(activeByPrimalDual(0.0, 1e-9, c));   // open, no pressure
    EXPECT_FALSE(activeByPrimalDual(-1e3, 0.0, c));   // tensile: release
    // The two terms compete: pressure 1e6 against a gap of 1e-7 (c g = 1e7)
    EXPECT_FALSE(activeByPrimalDual(1e6, 1e-7, c));
}

TEST(lagrangeMultiplier, activeSetUpdateCountsChanges)
{
    std::vector<double> lambda{1e6, 0.0, -1.0, 0.0};
    std::vector<double> gap{0.0, -1e-9, 0.0, 1e-6};
    std::vector<char> active{0, 1, 1, 0};
    EXPECT_EQ(updateActiveSet(lambda, gap, 1e12, active), 2);
    EXPECT_EQ(active, (std::vector<char>{1, 1, 0, 0}));
    EXPECT_EQ(updateActiveSet(lambda, gap, 1e12, active), 0);
    std::vector<char> wrong(3, 0);
    EXPECT_THROW(updateActiveSet(lambda, gap, 1e12, wrong), std::invalid_argument);
}

TEST(firstContact, onlyTheShallowPenetrationsWait)
{
    const double d = 2e-5, h = 1e-3;
    EXPECT_FALSE(waitsAtFirstContact(-d, d, h));          // the deepest enters
    EXPECT_FALSE(waitsAtFirstContact(-0.5*d, d, h));      // at the fraction
    EXPECT_TRUE(waitsAtFirstContact(-0.49*d, d, h));
    EXPECT_TRUE(waitsAtFirstContact(-1e-30, d, h));
    EXPECT_FALSE(waitsAtFirstContact(0.0, d, h));         // touching, open
    EXPECT_FALSE(waitsAtFirstContact(1e-6, d, h));        // open faces untouched
    // Nothing penetrates (or a degenerate deepest): nobody waits
    EXPECT_FALSE(waitsAtFirstContact(-1e-6, 0.0, h));
    EXPECT_FALSE(waitsAtFirstContact(-1e-6, -1.0, h));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(waitsAtFirstContact(nan, d, h));
    EXPECT_FALSE(waitsAtFirstContact(-1e-6, nan, h));
    EXPECT_FALSE(waitsAtFirstContact(-1e-6, d, nan));
    // Meshed touching surfaces: gaps of round-off, every face enters
    EXPECT_FALSE(waitsAtFirstContact(-1e-13, 2.7e-13, h));
    EXPECT_TRUE(waitsAtFirstContact(-1e-13, 2.7e-13, 1e-6));
    for (const double g : {-1e-12, 1e-12, -0.0, 0.0})
    {
        EXPECT_FALSE(waitsAtFirstContact(g, 1e-11, h)) << g;
    }
    // A deepest of inf (a broken search) holds every finite penetration
    // back but lets the infinite one through: nothing divides by it
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(waitsAtFirstContact(-1.0, inf, h));
    EXPECT_FALSE(waitsAtFirstContact(-inf, inf, h));
    EXPECT_FALSE(waitsAtFirstContact(inf, d, h));
    EXPECT_FALSE(waitsAtFirstContact(-1e-6, d, inf));   // floor above all
}

TEST(firstContact, hertzSphereEntersItsContactRadius)
{
    // Overlap depth delta - r^2/(2 R) of a sphere pressed delta into a
    // plane; Hertz: a^2 = R delta. The faces that enter are those inside a.
    const double R = 0.05, delta = 1e-5, h = 1e-3;
    const double a = std::sqrt(R*delta);
    for (int i = 0; i <= 40; ++i)
    {
        const double r = 1.5*a*i/40.0;
        const double gap = r*r/(2*R) - delta;
        const bool enters = gap < 0 && !waitsAtFirstContact(gap, delta, h);
        if (std::abs(r - a) > 1e-12*a)
        {
            EXPECT_EQ(enters, r < a) << "r/a = " << r/a;
        }
    }
}
