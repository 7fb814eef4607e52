// Unit tests of the active-set rule of direct constraint elimination,
// src/kernels/contact/directEliminationLaw (Wriggers, Computational
// Contact Mechanics, 2nd ed. 2006, ch. 6, chapter eq. 2.16-2.19): a free
// face enters when it penetrates, an eliminated face stays while its
// reaction presses. Swept over gaps and reactions of +-1e-12 to 1e12,
// exact zeros and NaN; and against the Lagrange multiplier's primal-dual
// rule, whose fixed points it shares.

#include "directEliminationLaw.H"
#include "normalContactLaws.H"

#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include <vector>

using namespace c4f::contact;

namespace
{

const std::vector<double> magnitudes{1e-300, 1e-12, 1e-6, 1.0, 1e6, 1e12};

} // End anonymous namespace


TEST(directEliminationLaw, freeFaceEntersWhenItPenetrates)
{
    for (const double m : magnitudes)
    {
        // The reaction of a free face (its solve's residual traction) does
        // not decide: only its gap
        for (const double p : {-m, 0.0, m})
        {
            EXPECT_TRUE(directEliminationActive(false, p, -m)) << m << " " << p;
            EXPECT_FALSE(directEliminationActive(false, p, m)) << m << " " << p;
        }
    }
    // A touching face has not penetrated
    EXPECT_FALSE(directEliminationActive(false, 1.0, 0.0));
    EXPECT_FALSE(directEliminationActive(false, 1.0, -0.0));
}

TEST(directEliminationLaw, eliminatedFaceStaysWhileItPresses)
{
    for (const double m : magnitudes)
    {
        // The gap of an eliminated face is zero up to the solve's
        // round-off and the geometry's lag; its sign does not decide
        for (const double g : {-m, 0.0, m})
        {
            EXPECT_TRUE(directEliminationActive(true, m, g)) << m << " " << g;
            EXPECT_FALSE(directEliminationActive(true, -m, g)) << m << " " << g;
        }
    }
    // No pressure: nothing to transmit, released
    EXPECT_FALSE(directEliminationActive(true, 0.0, -1.0));
    EXPECT_FALSE(directEliminationActive(true, -0.0, -1.0));
}

TEST(directEliminationLaw, undefinedStateIsNotConstrained)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(directEliminationActive(false, 1.0, nan));
    EXPECT_FALSE(directEliminationActive(true, nan, -1.0));
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(directEliminationActive(false, 0.0, -inf));
    EXPECT_FALSE(directEliminationActive(false, 0.0, inf));
}

TEST(directEliminationLaw, sameFixedPointsAsThePrimalDualRule)
{
    // At a fixed point an eliminated face has g = 0 and a free face p = 0
    // (lambda = 0). There the primal-dual rule lambda - c g > 0 gives the
    // same answer for every c > 0
    for (const double c : {1e-6, 1.0, 1e9, 1e15})
    {
        for (const double m : magnitudes)
        {
            for (const double p : {-m, m})
            {
                EXPECT_EQ(directEliminationActive(true, p, 0.0), activeByPrimalDual(p, 0.0, c))
                    << c << " " << p;
            }
            for (const double g : {-m, m})
            {
                EXPECT_EQ(directEliminationActive(false, 0.0, g), activeByPrimalDual(0.0, g, c))
                    << c << " " << g;
            }
        }
    }
}
