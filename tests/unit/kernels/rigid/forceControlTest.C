// Unit tests of the force-controlled tool's position update, src/kernels/
// rigid/forceControl: the secant iteration finds the root of smooth
// monotone force laws (linear in one step, Hertz's s^(3/2) superlinearly),
// k0 stands in where the secant is missing or not positive, the step is
// bounded, and bad coefficients throw.

#include "forceControl.H"
#include "../fpeTraps.H"

#include <gtest/gtest.h>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <cfenv>

using namespace c4f::rigid;

namespace
{

//- Iterate the update on P(s) from s0 until converged; the iterations
int solve
(
    const std::function<double(double)>& P,
    const double s0,
    const double Pt,
    const double k0,
    const double maxStep,
    double& s
)
{
    ForceControlState st;
    st.s = s0;
    st.P = P(s0);
    for (int it = 0; it < 100; ++it)
    {
        if (forceControlConverged(st.P, Pt, 1e-12))
        {
            s = st.s;
            return it;
        }
        const double sNew = forceControlUpdate(st, Pt, k0, maxStep);
        st.sPrev = st.s;
        st.PPrev = st.P;
        st.havePrev = true;
        st.s = sNew;
        st.P = P(sNew);
    }
    s = st.s;
    return 100;
}

} // End anonymous namespace


TEST(ForceControl, linearLawInOneSecantStep)
{
    const FpeTraps traps(FE_OVERFLOW | FE_DIVBYZERO | FE_INVALID);
    // k0 ten times the true stiffness: the first step falls short, the
    // secant then lands on the root
    const auto P = [](double s) { return 3e8*s; };
    double s = 0;
    const int n = solve(P, 1e-4, 6e4, 3e9, 1.0, s);
    EXPECT_LE(n, 3);
    EXPECT_NEAR(s, 2e-4, 1e-15);
}


TEST(ForceControl, hertzLawConvergesSuperlinearly)
{
    const FpeTraps traps(FE_OVERFLOW | FE_DIVBYZERO | FE_INVALID);
    // F = (4/3) E* R^(1/2) s^(3/2) of the rigidSphere tutorial
    const double Es = 2e11/0.91;
    const double R = 0.1;
    const auto P = [&](double s)
    {
        return s > 0 ? 4.0/3.0*Es*std::sqrt(R)*std::pow(s, 1.5) : 0.0;
    };
    const double sTrue = 1e-3;
    for (const double s0 : {2e-4, 5e-4, 8e-4, 1.5e-3})
    {
        double s = 0;
        const int n = solve(P, s0, P(sTrue), 10*1.5*P(1e-3)/1e-3, 1e-3, s);
        EXPECT_LT(n, 15) << "s0 = " << s0;
        EXPECT_NEAR(s, sTrue, 1e-12) << "s0 = " << s0;
    }
}


TEST(ForceControl, slopeFallsBackToK0)
{
    ForceControlState st;
    st.s = 1;
    st.P = 5;
    EXPECT_EQ(forceControlSlope(st, 7), 7);  // no previous state
    st.havePrev = true;
    st.sPrev = 1;
    st.PPrev = 4;
    EXPECT_EQ(forceControlSlope(st, 7), 7);  // no step
    st.sPrev = 0.5;
    st.PPrev = 6;
    EXPECT_EQ(forceControlSlope(st, 7), 7);  // force fell as s grew
    st.PPrev = 4;
    EXPECT_DOUBLE_EQ(forceControlSlope(st, 7), 2);
}


TEST(ForceControl, stepIsBounded)
{
    ForceControlState st;
    st.s = 0;
    st.P = 0;
    EXPECT_DOUBLE_EQ(forceControlUpdate(st, 1e9, 1, 1e-3), 1e-3);
    EXPECT_DOUBLE_EQ(forceControlUpdate(st, -1e9, 1, 1e-3), -1e-3);
}


TEST(ForceControl, badCoefficientsThrow)
{
    const ForceControlState st;
    EXPECT_THROW(forceControlUpdate(st, 1, 0, 1), std::invalid_argument);
    EXPECT_THROW(forceControlUpdate(st, 1, -1, 1), std::invalid_argument);
    EXPECT_THROW(forceControlUpdate(st, 1, 1, 0), std::invalid_argument);
    EXPECT_THROW
    (
        forceControlUpdate(st, 1, INFINITY, 1), std::invalid_argument
    );
    EXPECT_THROW(forceControlUpdate(st, 1, 1, NAN), std::invalid_argument);
}


TEST(ForceControl, convergedRelativeAndAbsolute)
{
    EXPECT_TRUE(forceControlConverged(1.0 + 1e-7, 1.0, 1e-6));
    EXPECT_FALSE(forceControlConverged(1.0 + 1e-5, 1.0, 1e-6));
    EXPECT_TRUE(forceControlConverged(1e-7, 0.0, 1e-6));
}
