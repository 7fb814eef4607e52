// Unit tests of Nitsche's contact law, src/kernels/contact/nitscheLaw
// (Chouly & Hild 2013; Chouly, Hild & Renard 2015; Wriggers, Computational
// Contact Mechanics, 2nd ed. 2006, ch. 6, chapter eq. 2.24-2.30):
// p = <-sigma_n - gamma g>. Both slopes against central differences over
// gaps, stresses and gamma from 1e-12 to 1e12 in scale; consistency (the
// exact contact state satisfies the law for every gamma > 0); the mean
// flux of two bodies; the implicit form (a spring of compliance 1/gamma
// about -sigma_n); and its fixed point on a scalar model of two bodies
// with a lagged flux, which is the contact state whatever gamma.

#include "nitscheLaw.H"
#include "linearizedNormalLaw.H"

#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include <vector>

using namespace c4f::contact;

namespace
{

// Steel over a 1 mm cell: the penalty-like scale E/h
const double stiffness = 2.1e14;

} // End anonymous namespace


TEST(nitscheLaw, valueAndClipping)
{
    const double gamma = 1e12;
    // Pressing flux, closed gap: the flux is the pressure
    EXPECT_DOUBLE_EQ(nitschePressure(0.0, -3e6, gamma).pressure, 3e6);
    // Penetration adds gamma (-g); an open gap subtracts gamma g
    EXPECT_DOUBLE_EQ(nitschePressure(-1e-6, -3e6, gamma).pressure, 4e6);
    EXPECT_DOUBLE_EQ(nitschePressure(1e-6, -3e6, gamma).pressure, 2e6);
    // Clipped: it cannot pull
    EXPECT_EQ(nitschePressure(1e-5, -3e6, gamma).pressure, 0.0);
    EXPECT_EQ(nitschePressure(0.0, 3e6, gamma).pressure, 0.0);
    EXPECT_EQ(nitschePressure(0.0, 0.0, gamma).pressure, 0.0);
    // gamma = gamma0 E/h
    EXPECT_DOUBLE_EQ(nitscheStabilisation(10, stiffness), 2.1e15);
    EXPECT_DOUBLE_EQ(nitscheNormalStress(-2e6, -4e6), -3e6);
}

TEST(nitscheLaw, slopesAgainstCentralDifferences)
{
    for (const double gamma0 : {1e-3, 1.0, 10.0, 100.0, 1e4})
    {
        const double gamma = nitscheStabilisation(gamma0, stiffness);
        for (const double s : {-1e9, -1e6, -1.0, 1.0, 1e6})
        {
            for (const double g : {-1e-3, -1e-7, -1e-12, 1e-12, 1e-7, 1e-3})
            {
                const NitscheValue v = nitschePressure(g, s, gamma);
                const double p = -s - gamma*g;
                if (std::abs(p) < 1e-6*(std::abs(s) + gamma*std::abs(g)))
                {
                    continue;   // at the kink the central difference straddles it
                }
                // Steps small enough to stay on one side of the kink
                const double hg = 1e-4*std::abs(p)/gamma;
                const double hs = 1e-4*std::abs(p);
                const double dg =
                    (nitschePressure(g + hg, s, gamma).pressure
                   - nitschePressure(g - hg, s, gamma).pressure)/(2*hg);
                const double ds =
                    (nitschePressure(g, s + hs, gamma).pressure
                   - nitschePressure(g, s - hs, gamma).pressure)/(2*hs);
                // Round-off of the difference: eps |p| / h
                const double tolG = 1e-10*gamma + 4e-16*(std::abs(s) + gamma*std::abs(g))/hg;
                const double tolS = 1e-10 + 4e-16*(std::abs(s) + gamma*std::abs(g))/hs;
                EXPECT_NEAR(v.dPressureDGap, dg, tolG) << gamma0 << " " << s << " " << g;
                EXPECT_NEAR(v.dPressureDNormalStress, ds, tolS) << gamma0 << " " << s << " " << g;
                EXPECT_EQ(v.dPressureDGap, p > 0 ? -gamma : 0.0);
                EXPECT_EQ(v.dPressureDNormalStress, p > 0 ? -1.0 : 0.0);
            }
        }
    }
}

TEST(nitscheLaw, consistentForEveryGamma)
{
    // The exact contact states satisfy p = <-sigma_n - gamma g> whatever
    // gamma: pressing (g = 0, p = -sigma_n > 0) and apart (sigma_n = 0,
    // p = 0, g >= 0); the penalty p = eps <-g> does not (it needs g < 0)
    for (const double gamma0 : {1e-6, 1.0, 10.0, 100.0, 1e6})
    {
        const double gamma = nitscheStabilisation(gamma0, stiffness);
        for (const double p : {1e-3, 1.0, 3e6, 1e10})
        {
            EXPECT_EQ(nitschePressure(0.0, -p, gamma).pressure, p) << gamma0 << " " << p;
        }
        for (const double g : {0.0, 1e-12, 1e-6, 1.0})
        {
            EXPECT_EQ(nitschePressure(g, 0.0, gamma).pressure, 0.0) << gamma0 << " " << g;
        }
    }
}

TEST(nitscheLaw, implicitFormIsASpringAboutTheFlux)
{
    // Linearised at any pressing state: g = (1/gamma)(p0 - p), p0 = -sigma_n
    const double gamma = nitscheStabilisation(10, stiffness);
    for (const double s : {-1e9, -3e6, -1.0})
    {
        for (const double g : {-1e-9, 0.0, 1e-19})
        {
            const NitscheValue v = nitschePressure(g, s, gamma);
            ASSERT_GT(v.pressure, 0.0);
            const LinearizedNormalLaw lin =
                linearizeNormalLaw({v.pressure, v.dPressureDGap}, g);
            EXPECT_TRUE(lin.coupled);
            EXPECT_NEAR(lin.compliance, 1/gamma, 1e-15/gamma);
            EXPECT_NEAR(lin.pressure0, -s, 1e-12*std::abs(s) + 1e-9);
        }
    }
    // Released: not coupled, no pressure
    const NitscheValue v = nitschePressure(1e-3, -1.0, gamma);
    const LinearizedNormalLaw lin = linearizeNormalLaw({v.pressure, v.dPressureDGap}, 1e-3);
    EXPECT_FALSE(lin.coupled);
    EXPECT_EQ(lin.pressure0, 0.0);
}

TEST(nitscheLaw, laggedFluxConvergesToTheContactState)
{
    // Scalar model of the solver's iteration: the bodies answer a face
    // pressure p with the gap g = -d + p/kb (interference d, series
    // stiffness kb), and the flux of the cells lags the face by a whole
    // corrector, sigma_n = -p_prev (the worst lag). Each corrector holds the
    // law implicitly, linearised at the last state (g = C (p0 - p),
    // C = 1/gamma, p0 = -sigma_n):
    //   p = (p_prev + gamma d)/(1 + gamma/kb),
    // whose fixed point is p = kb d, g = 0 for every gamma (no penalty
    // offset), reached with the contraction 1/(1 + gamma/kb).
    const double kb = 1e14, d = 1e-8, exact = kb*d;
    for (const double gamma0 : {1.0, 10.0, 100.0})
    {
        const double gamma = nitscheStabilisation(gamma0, kb);
        double p = 0, g = -d;
        int it = 0;
        for (; it < 200 && std::abs(p - exact) > 1e-12*exact; ++it)
        {
            const NitscheValue v = nitschePressure(g, -p, gamma);
            const LinearizedNormalLaw lin =
                linearizeNormalLaw({v.pressure, v.dPressureDGap}, g);
            ASSERT_TRUE(lin.coupled) << gamma0 << " " << it;
            p = (lin.compliance*lin.pressure0 + d)/(lin.compliance + 1/kb);
            g = -d + p/kb;
        }
        EXPECT_NEAR(p, exact, 1e-12*exact) << gamma0;
        // The contraction 1/(1 + gamma0): 12/log10(1 + gamma0) correctors
        // to 1e-12 (gamma0 = 1: 40, 10: 12, 100: 6)
        EXPECT_LE(it, int(12/std::log10(1 + gamma0)) + 2) << gamma0;
        EXPECT_NEAR(g, 0.0, 1e-12*d) << gamma0;
    }
}

TEST(nitscheLaw, parameterValidity)
{
    EXPECT_TRUE(validNitscheParameter(10));
    EXPECT_TRUE(validNitscheParameter(1e-12));
    EXPECT_FALSE(validNitscheParameter(0));
    EXPECT_FALSE(validNitscheParameter(-1));
    EXPECT_FALSE(validNitscheParameter(std::numeric_limits<double>::infinity()));
    EXPECT_FALSE(validNitscheParameter(std::numeric_limits<double>::quiet_NaN()));
    EXPECT_NE(describeNitscheParameterRequirement().find("positive"), std::string::npos);
}

TEST(nitscheLaw, stiffnessWeights)
{
    // Like bodies and cells: the plain mean
    EXPECT_DOUBLE_EQ(nitscheSlaveWeight(stiffness, stiffness), 0.5);
    // Each body's weight its compliance share: the soft slave of a 1000:1
    // pair carries 1000/1001 of the flux
    EXPECT_NEAR(nitscheSlaveWeight(stiffness, 1000*stiffness), 1000.0/1001, 1e-15);
    EXPECT_NEAR(nitscheSlaveWeight(1000*stiffness, stiffness), 1.0/1001, 1e-15);
    // A rigid master: the slave alone; no master (out of reach): the slave
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(nitscheSlaveWeight(stiffness, inf), 1.0);
    EXPECT_EQ(nitscheSlaveWeight(stiffness, 0.0), 1.0);
    EXPECT_EQ(nitscheSlaveWeight(stiffness, -1.0), 1.0);
    EXPECT_EQ(nitscheSlaveWeight(stiffness, std::numeric_limits<double>::quiet_NaN()), 1.0);
    // Consistent: any weights give the contact pressure at the exact state
    for (const double ks : {1e9, stiffness, 1e18})
    {
        const double w = nitscheSlaveWeight(ks, stiffness);
        EXPECT_GE(w, 0.0);
        EXPECT_LE(w, 1.0);
        const double p = 3e6;
        EXPECT_NEAR(nitschePressure(0.0, w*(-p) + (1 - w)*(-p), 10*ks).pressure, p, 1e-9*p);
    }
}
