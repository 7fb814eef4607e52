// Unit tests of the clamped log barrier of Incremental Potential Contact,
// src/kernels/contact/barrierLaw (Li et al. 2020; Wriggers 2006, ch. 6,
// chapter eq. 2.34-2.37). The derivatives are checked against central
// differences with tolerances built from the step (truncation from the
// next derivative's bound, rounding from the values); the law is swept
// over its degenerate inputs (d -> 0+, d = dhat, d > dhat, d <= 0, NaN)
// and must stay finite and of the right sign; the step limiter must keep
// every gap at its fraction; Newton with the law's tangent and the limiter
// must solve a spring in series with the barrier from both sides without
// a gap ever reaching zero.

#include "barrierLaw.H"
#include "linearizedNormalLaw.H"
#include "../fpeTraps.H"

#include <gtest/gtest.h>
#include <cfenv>
#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

using namespace c4f::contact;

namespace
{

// The closed forms as written in the papers, for comparison away from
// d = dhat (where they lose digits and the kernel does not)
double bRef(const double d, const double dh)
{
    return -(d - dh)*(d - dh)*std::log(d/dh);
}

double dbRef(const double d, const double dh)
{
    return (dh - d)*(2*std::log(d/dh) - dh/d + 1);
}

double d2bRef(const double d, const double dh)
{
    return (dh/d + 2)*dh/d - 2*std::log(d/dh) - 3;
}

// Bounds of |b'''| and |b''''| on [d - h, d + h] (both fall with d)
double b3Bound(const double d, const double dh)
{
    return 2*(dh*dh/(d*d*d) + dh/(d*d) + 1/d);
}

double b4Bound(const double d, const double dh)
{
    return 6*dh*dh/(d*d*d*d) + 4*dh/(d*d*d) + 2/(d*d);
}

// The tolerance of a central difference (fPlus - fMinus)/(2h) of f at x
// with slope f': the truncation given, the rounding of both values (a few
// ulp over 2h) and that of the abscissae x +- h (an ulp of x times the
// slope, over h)
double fdTolerance
(
    const double truncation,
    const double fPlus,
    const double fMinus,
    const double slope,
    const double x,
    const double h
)
{
    return
        truncation
      + 4*DBL_EPSILON*std::max(std::abs(fPlus), std::abs(fMinus))/h
      + 2*DBL_EPSILON*std::abs(slope)*(x + h)/h;
}

const std::vector<double> fractions =
    {1e-6, 1e-3, 0.01, 0.1, 0.25, 0.5, 0.75, 0.9, 0.99, 0.999};

} // End anonymous namespace


TEST(barrierLaw, closedForms)
{
    for (const double dh : {1e-9, 2.7e-7, 1e-4, 1.0, 1e3})
    {
        for (const double f : {1e-6, 1e-3, 0.1, 0.5, 0.7})
        {
            const double d = f*dh;
            const BarrierValue v = barrier(d, dh);
            EXPECT_NEAR(v.b, bRef(d, dh), 1e-13*std::abs(bRef(d, dh))) << d;
            EXPECT_NEAR(v.db, dbRef(d, dh), 1e-12*std::abs(dbRef(d, dh))) << d;
            EXPECT_NEAR(v.d2b, d2bRef(d, dh), 1e-12*std::abs(d2bRef(d, dh))) << d;
            EXPECT_GT(v.b, 0);
            EXPECT_LT(v.db, 0);
            EXPECT_GT(v.d2b, 0);
        }
    }
}

TEST(barrierLaw, firstDerivativeMatchesCentralDifferences)
{
    for (const double dh : {2.7e-7, 1e-4, 1.0})
    {
        for (const double f : fractions)
        {
            const double d = f*dh;
            const double h = 1e-4*std::min(d, dh - d);
            const double bp = barrier(d + h, dh).b, bm = barrier(d - h, dh).b;
            const double fd = (bp - bm)/(2*h);
            const double tol = fdTolerance
            (
                h*h/6*b3Bound(d - h, dh), bp, bm, barrier(d, dh).db, d, h
            );
            EXPECT_NEAR(barrier(d, dh).db, fd, tol) << "d/dhat = " << f;
        }
    }
}

TEST(barrierLaw, secondDerivativeMatchesCentralDifferences)
{
    for (const double dh : {2.7e-7, 1e-4, 1.0})
    {
        for (const double f : fractions)
        {
            const double d = f*dh;
            const double h = 1e-4*std::min(d, dh - d);
            const double gp = barrier(d + h, dh).db, gm = barrier(d - h, dh).db;
            const double fd = (gp - gm)/(2*h);
            const double tol = fdTolerance
            (
                h*h/6*b4Bound(d - h, dh), gp, gm, barrier(d, dh).d2b, d, h
            );
            EXPECT_NEAR(barrier(d, dh).d2b, fd, tol) << "d/dhat = " << f;
        }
    }
}

TEST(barrierLaw, pressureIsMinusKappaBPrimeWithItsSlope)
{
    const double dh = 1e-4, kappa = 1e7;
    for (const double f : fractions)
    {
        const double g = f*dh;
        const NormalLawValue p = barrierPressure(g, dh, kappa);
        const BarrierValue v = barrier(g, dh);
        EXPECT_EQ(p.pressure, -kappa*v.db);
        EXPECT_EQ(p.dPressureDGap, -kappa*v.d2b);
        EXPECT_GT(p.pressure, 0);
        EXPECT_LT(p.dPressureDGap, 0);

        const double h = 1e-4*std::min(g, dh - g);
        const double pp = barrierPressure(g + h, dh, kappa).pressure;
        const double pm = barrierPressure(g - h, dh, kappa).pressure;
        const double tol = fdTolerance
        (
            kappa*h*h/6*b4Bound(g - h, dh), pp, pm, p.dPressureDGap, g, h
        );
        EXPECT_NEAR(p.dPressureDGap, (pp - pm)/(2*h), tol) << "g/dhat = " << f;
    }
    // Far inside, p -> kappa dhat^2/g (the gap that carries p is about
    // kappa dhat^2/p): relative error of order (g/dhat) ln(dhat/g)
    for (const double f : {1e-4, 1e-6, 1e-9})
    {
        const double g = f*dh;
        EXPECT_NEAR
        (
            barrierPressure(g, dh, kappa).pressure*g/(kappa*dh*dh),
            1.0,
            5*f*std::log(1/f)
        ) << f;
    }
}

TEST(barrierLaw, smoothClampAtDhat)
{
    // b, b', b'' are zero at and beyond dhat and go to zero continuously:
    // b ~ u^2 dhat^2 u, b' ~ -3 dhat u^2, b'' ~ 6 u for u = 1 - d/dhat -> 0
    const double dh = 1e-4;
    for (const double g : {dh, 1.5*dh, 1e3*dh, DBL_MAX})
    {
        const BarrierValue v = barrier(g, dh);
        EXPECT_EQ(v.b, 0.0) << g;
        EXPECT_EQ(v.db, 0.0) << g;
        EXPECT_EQ(v.d2b, 0.0) << g;
        const NormalLawValue p = barrierPressure(g, dh, 1e9);
        EXPECT_EQ(p.pressure, 0.0);
        EXPECT_EQ(p.dPressureDGap, 0.0);
    }
    for (const double u : {1e-3, 1e-6, 1e-9, 1e-12})
    {
        const double d = dh*(1 - u);
        const double uExact = (dh - d)/dh;     // u as the double d holds it
        const BarrierValue v = barrier(d, dh);
        EXPECT_NEAR(v.db, -3*dh*uExact*uExact, 4*uExact*dh*uExact*uExact) << u;
        EXPECT_NEAR(v.d2b, 6*uExact, 8*uExact*uExact + 1e-15) << u;
        EXPECT_NEAR(v.b, dh*dh*uExact*uExact*uExact, 2*dh*dh*uExact*uExact*uExact*uExact)
            << u;
    }
    // The last double below dhat: still positive, tiny
    const double below = std::nextafter(dh, 0.0);
    EXPECT_GT(barrier(below, dh).d2b, 0.0);
    EXPECT_LT(barrier(below, dh).d2b, 1e-14);
}

TEST(barrierLaw, towardsZeroGapFiniteAndMonotone)
{
    // d -> 0+: the pressure and the tangent grow without bound, but every
    // value is finite (saturated at DBL_MAX), positive and never falls
    const double dh = 1e-4, kappa = 1e15;
    double pPrev = 0, tPrev = 0;
    for (int k = 1; k <= 330; ++k)
    {
        const double g = dh*std::pow(10.0, -k);
        const NormalLawValue p = barrierPressure(g, dh, kappa);
        const BarrierValue v = barrier(g, dh);
        EXPECT_TRUE(std::isfinite(p.pressure)) << g;
        EXPECT_TRUE(std::isfinite(p.dPressureDGap)) << g;
        EXPECT_TRUE(std::isfinite(v.b) && std::isfinite(v.db) && std::isfinite(v.d2b)) << g;
        EXPECT_GE(p.pressure, pPrev) << g;
        EXPECT_GE(-p.dPressureDGap, tPrev) << g;
        pPrev = p.pressure;
        tPrev = -p.dPressureDGap;
    }
    EXPECT_EQ(pPrev, DBL_MAX);
}

TEST(barrierLaw, infeasibleGapsSaturateNeverNaN)
{
    // d <= 0 (touching or penetrating) is outside the domain: the largest
    // values, never NaN; so is a NaN gap
    for (const double g :
        {0.0, -0.0, -1e-300, -1e-12, -1.0, -DBL_MAX,
         -std::numeric_limits<double>::infinity(),
         std::numeric_limits<double>::quiet_NaN()})
    {
        const BarrierValue v = barrier(g, 1e-4);
        EXPECT_EQ(v.b, DBL_MAX) << g;
        EXPECT_EQ(v.db, -DBL_MAX) << g;
        EXPECT_EQ(v.d2b, DBL_MAX) << g;
        const NormalLawValue p = barrierPressure(g, 1e-4, 1e12);
        EXPECT_EQ(p.pressure, DBL_MAX) << g;
        EXPECT_EQ(p.dPressureDGap, -DBL_MAX) << g;
    }
}

TEST(barrierLaw, gapForPressureInvertsThePressure)
{
    // With the traps OpenFOAM's FOAM_SIGFPE sets: no overflow on the way
    feenableexcept(FE_OVERFLOW | FE_DIVBYZERO | FE_INVALID);
    // Round trips over the whole range of the inverse: from a gap a hair
    // below dhat (p ~ 3 kappa dhat u^2) to 1e-99 dhat (p ~ kappa dhat 1e99),
    // for stiffnesses from soft to stiff
    for (const double dh : {1e-7, 1e-4, 1.0})
    {
        for (const double kappa : {1.0, 1e7, 1e15})
        {
            for (int k = 0; k <= 99; ++k)
            {
                const double g = dh*(k == 0 ? 1 - 1e-6 : std::pow(10.0, -k));
                const double p = barrierPressure(g, dh, kappa).pressure;
                ASSERT_TRUE(p > 0 && p < DBL_MAX) << g;
                const double back = barrierGapForPressure(p, dh, kappa);
                EXPECT_NEAR(back, g, 1e-12*g) << "dhat " << dh << " kappa " << kappa;
                EXPECT_GT(back, 0.0);
                EXPECT_LT(back, dh);
            }
        }
    }
    fedisableexcept(FE_ALL_EXCEPT);
}

TEST(barrierLaw, gapForPressureDegenerateInputs)
{
    // No pressure (or NaN): the face is at dhat, where the law starts; a
    // pressure beyond the law's at 1e-100 dhat: that gap, still > 0
    const double dh = 1e-4, kappa = 1e7;
    for (const double p :
        {0.0, -0.0, -1.0, -DBL_MAX, std::numeric_limits<double>::quiet_NaN()})
    {
        EXPECT_EQ(barrierGapForPressure(p, dh, kappa), dh) << p;
    }
    feenableexcept(FE_OVERFLOW | FE_DIVBYZERO);
    for (const double p :
        {DBL_MAX, std::numeric_limits<double>::infinity()})
    {
        const double g = barrierGapForPressure(p, dh, kappa);
        EXPECT_GT(g, 0.0) << p;
        EXPECT_NEAR(g, 1e-100*dh, 1e-110*dh) << p;
    }
    // The tangent at the inverted gap: its secant to a nearby pressure
    // agrees (the inverse is differentiable with slope 1/p')
    const double p0 = 1e4, dp = 1e-3;
    const double g0 = barrierGapForPressure(p0, dh, kappa);
    const double slope = barrierPressure(g0, dh, kappa).dPressureDGap;
    const double fd =
        (barrierGapForPressure(p0 + dp, dh, kappa)
       - barrierGapForPressure(p0 - dp, dh, kappa))/(2*dp);
    EXPECT_NEAR(fd*slope, 1.0, 1e-6);
    fedisableexcept(FE_ALL_EXCEPT);
}

TEST(barrierLaw, linearisationGapIsTheReactionsWhereNewtonCreeps)
{
    const FpeTraps traps(FE_OVERFLOW | FE_DIVBYZERO | FE_INVALID);
    const double dh = 1e-4, kappa = 1e7;
    const double NaN = std::numeric_limits<double>::quiet_NaN();
    // The patch test's state: p_r = 1e4 Pa, whose gap is G ~ 1.2e-5 m
    const double pr = 1e4;
    const double G = barrierGapForPressure(pr, dh, kappa);
    ASSERT_GT(G, 1e-6);
    ASSERT_LT(G, 0.5*dh);
    // A face the limiter took far below G: linearised at G, whose
    // tangent predicts the gap that carries p_r (the point is on the law)
    for (const double g : {1e-17, 1e-10, 0.099*G})
    {
        const double gs = barrierLinearisationGap(g, pr, dh, kappa);
        EXPECT_DOUBLE_EQ(gs, G) << g;
        EXPECT_NEAR(barrierPressure(gs, dh, kappa).pressure, pr, 1e-9*pr);
    }
    // Within a factor of ten of G, or beyond it: Newton from g itself
    for (const double g : {0.11*G, 0.5*G, G, 2*G, 0.99*dh, dh})
    {
        EXPECT_EQ(barrierLinearisationGap(g, pr, dh, kappa), g) << g;
    }
    // A small reaction (G near dhat) is capped at dhat/2, and never
    // below g: over a sweep of gaps and reactions g <= g* <= max(g, dhat/2)
    for (int i = 0; i <= 40; ++i)
    {
        const double g = dh*std::pow(10.0, -0.25*i);
        for (const double p : {1e-6, 1.0, 1e2, 1e4, 1e6, 1e9, 1e15})
        {
            const double gs = barrierLinearisationGap(g, p, dh, kappa);
            EXPECT_GE(gs, g) << g << " " << p;
            EXPECT_LE(gs, std::max(g, 0.5*dh)) << g << " " << p;
        }
    }
    EXPECT_EQ(barrierLinearisationGap(1e-8, 1e-6, dh, kappa), 0.5*dh);
    // No compressive reaction, NaN, or a gap that is not open: g itself
    // (the method refuses closed gaps before it gets here); quietly, with
    // the invalid-operation trap on
    for (const double p : {0.0, -1.0, -DBL_MAX, NaN})
    {
        EXPECT_EQ(barrierLinearisationGap(1e-8, p, dh, kappa), 1e-8) << p;
    }
    EXPECT_EQ(barrierLinearisationGap(0.0, pr, dh, kappa), 0.0);
    EXPECT_EQ(barrierLinearisationGap(-1e-8, pr, dh, kappa), -1e-8);
    EXPECT_TRUE(std::isnan(barrierLinearisationGap(NaN, pr, dh, kappa)));
    // A denormal reaction: the gap is about dhat, so dhat/2 for a close face
    for (const double p : {1e-300, 1e-310, 4.9e-324})
    {
        EXPECT_EQ(barrierLinearisationGap(1e-8, p, 1e-3, 1e13), 0.5e-3) << p;
        const double G = barrierGapForPressure(p, 1e-3, 1e13);
        EXPECT_GT(G, 0.99e-3) << p;
        EXPECT_LE(G, 1e-3) << p;
    }
}

TEST(barrierLaw, stepLimitKeepsTheFraction)
{
    for (const double fr : {0.1, 0.2, 0.5})
    {
        for (const double g0 : {1e-300, 1e-9, 1e-4, 1.0})
        {
            // Not shrinking below the fraction: the whole step
            for (const double ratio : {fr, 0.5 + fr/2, 1.0, 2.0, 1e300})
            {
                EXPECT_EQ(barrierStepLimit(g0, ratio*g0, fr), 1.0);
            }
            // Shrinking further, penetrating, or far through: the gap
            // along the scaled step is the fraction of the gap before
            for (const double ratio : {0.99*fr, 0.0, -1.0, -1e6, -1e300})
            {
                const double g1 = ratio*g0;
                const double a = barrierStepLimit(g0, g1, fr);
                EXPECT_GT(a, 0) << ratio;
                EXPECT_LT(a, 1) << ratio;
                const double gA = g0 + a*(g1 - g0);
                EXPECT_NEAR(gA, fr*g0, 4*DBL_EPSILON*g0*(1 + std::abs(ratio)*a))
                    << "g0 " << g0 << " ratio " << ratio;
                EXPECT_GT(gA, 0);
            }
        }
    }
    // A start that is not open, or NaN, is not this function's to judge
    EXPECT_EQ(barrierStepLimit(0.0, -1.0, 0.2), 1.0);
    EXPECT_EQ(barrierStepLimit(-1.0, -2.0, 0.2), 1.0);
    EXPECT_EQ(barrierStepLimit(std::nan(""), -1.0, 0.2), 1.0);
    EXPECT_EQ(barrierStepLimit(1.0, std::nan(""), 0.2), 1.0);
    // -inf: the step is cut to nothing, never NaN
    EXPECT_EQ(barrierStepLimit(1.0, -std::numeric_limits<double>::infinity(), 0.2), 0.0);
}

TEST(barrierLaw, stiffnessIncreasesWhileTheGapKeepsShrinkingBelowTheFloor)
{
    EXPECT_TRUE(barrierStiffnessShouldIncrease(2e-7, 1e-7, 1e-6));
    EXPECT_FALSE(barrierStiffnessShouldIncrease(1e-7, 2e-7, 1e-6));   // growing
    EXPECT_FALSE(barrierStiffnessShouldIncrease(1e-7, 1e-7, 1e-6));   // steady
    EXPECT_FALSE(barrierStiffnessShouldIncrease(3e-6, 2e-6, 1e-6));   // above floor
    EXPECT_DOUBLE_EQ(barrierInitialStiffness(1.0, 1e6, 0.1), 1e7);
}

TEST(barrierLaw, parameterChecks)
{
    EXPECT_TRUE(validBarrierLength(1e-7));
    EXPECT_TRUE(validBarrierScale(1e-3));
    for (const double bad : {0.0, -0.0, -1e-9, std::nan(""),
                             std::numeric_limits<double>::infinity()})
    {
        EXPECT_FALSE(validBarrierLength(bad)) << bad;
        EXPECT_FALSE(validBarrierScale(bad)) << bad;
    }
    EXPECT_TRUE(validBarrierFraction(0.2));
    for (const double bad : {0.0, 1.0, -0.1, 1.5, std::nan("")})
    {
        EXPECT_FALSE(validBarrierFraction(bad)) << bad;
    }
}

TEST(barrierLaw, newtonWithLimiterSolvesASpringInSeries)
{
    // A column of stiffness k [Pa/m] closes an initial gap g0 by an
    // approach A: its pressure is k (A - (g0 - g)). Each outer corrector
    // solves the column with the barrier's tangent at the last gap
    // (the coupled spring g = C (p0 - p)), then the limiter keeps the new
    // gap at >= 0.2 of the old. The gap must stay positive at every
    // iterate and reach the root p_barrier(g) = k (A - g0 + g).
    const double dh = 1e-4, kappa = 1e7;
    for (const double k : {1e5, 1e7, 1e9})
    {
        for (const double g0 : {0.5*dh, 2*dh, 1e-2})
        {
            for (const double A : {1e-3, 1e-2})
            {
                double g = g0;
                int it = 0;
                double res = 1;
                for (; it < 200 && res > 1e-13; ++it)
                {
                    const LinearizedNormalLaw lin =
                        linearizeNormalLaw(barrierPressure(g, dh, kappa), g);
                    // p = p0 - g/C (coupled) or p = p0 (explicit) against
                    // p = k (A - g0 + g)
                    const double gNew =
                        lin.coupled
                      ? (lin.pressure0 - k*(A - g0))/(k + 1/lin.compliance)
                      : (lin.pressure0 - k*(A - g0))/k;
                    const double a = barrierStepLimit(g, gNew, 0.2);
                    const double gNext = g + a*(gNew - g);
                    ASSERT_GT(gNext, 0) << "k " << k << " g0 " << g0 << " A " << A;
                    res = std::abs(gNext - g)/dh;
                    g = gNext;
                }
                const double p = barrierPressure(g, dh, kappa).pressure;
                EXPECT_LT(it, 200) << "k " << k << " g0 " << g0 << " A " << A;
                EXPECT_GT(g, 0);
                if (A < g0 - dh)
                {
                    // The approach does not reach the barrier: free
                    EXPECT_NEAR(g, g0 - A, 1e-12*g0);
                    EXPECT_EQ(p, 0.0);
                }
                else
                {
                    EXPECT_NEAR(p, k*(A - g0 + g), 1e-9*p) << "k " << k << " g0 " << g0;
                    EXPECT_LT(g, dh);
                }
            }
        }
    }
}

TEST(barrierLaw, extensionIsTheBarrierAboveAndItsTangentBelow)
{
    const double dh = 1e-4, kappa = 1e7;
    for (const double f : {1e-6, 1e-4, 1e-2, 0.5})
    {
        const double gE = f*dh;
        const NormalLawValue e = barrierPressure(gE, dh, kappa);
        // Above gE (and beyond dhat) the barrier itself, bit for bit
        for (const double g : {gE, 1.5*gE, 0.7*dh, dh, 2*dh})
        {
            const NormalLawValue a = barrierPressureExtended(g, dh, kappa, gE);
            const NormalLawValue b = barrierPressure(g, dh, kappa);
            EXPECT_EQ(a.pressure, b.pressure) << f << " " << g;
            EXPECT_EQ(a.dPressureDGap, b.dPressureDGap) << f << " " << g;
        }
        // Below: the tangent line at gE, through g = 0 and far beyond
        double last = e.pressure;
        for (const double g : {0.999*gE, 0.5*gE, 0.0, -gE, -dh, -1.0})
        {
            const NormalLawValue a = barrierPressureExtended(g, dh, kappa, gE);
            EXPECT_TRUE(std::isfinite(a.pressure)) << f << " " << g;
            EXPECT_EQ(a.dPressureDGap, e.dPressureDGap) << f << " " << g;
            EXPECT_NEAR
            (
                a.pressure, e.pressure + e.dPressureDGap*(g - gE),
                4*DBL_EPSILON*std::abs(e.pressure + e.dPressureDGap*(g - gE))
            ) << f << " " << g;
            EXPECT_GT(a.pressure, last) << f << " " << g;
            last = a.pressure;
        }
        // C1 at gE: the one-sided difference quotients on either side
        // agree with the slope there (the law's curvature bounds the
        // truncation on the barrier's side)
        const double h = 1e-6*gE;
        const double pE = e.pressure;
        const double below =
            (pE - barrierPressureExtended(gE - h, dh, kappa, gE).pressure)/h;
        const double above =
            (barrierPressureExtended(gE + h, dh, kappa, gE).pressure - pE)/h;
        const double s = std::abs(e.dPressureDGap);
        EXPECT_NEAR(below, e.dPressureDGap, 1e-6*s) << f;
        EXPECT_NEAR(above, e.dPressureDGap, 1e-5*s) << f;
    }
    // NaN: saturated like the barrier, never NaN
    const NormalLawValue n =
        barrierPressureExtended(std::nan(""), dh, kappa, 1e-4*dh);
    EXPECT_FALSE(std::isnan(n.pressure));
    EXPECT_FALSE(std::isnan(n.dPressureDGap));
}

TEST(barrierLaw, newtonOnTheExtensionSolvesASpringInSeriesUnlimited)
{
    // The column of newtonWithLimiterSolvesASpringInSeries without the
    // limiter: Newton on the extended law from gaps the solve may take
    // through zero (an approach far beyond the barrier's range in one
    // step) reaches the law's root, the barrier's own above the
    // extension gap
    const double dh = 1e-4, kappa = 1e7, gE = 1e-4*dh;
    for (const double k : {1e5, 1e7, 1e9})
    {
        for (const double g0 : {0.5*dh, 2*dh, 1e-2})
        {
            for (const double A : {1e-3, 1e-2, 1e-1})
            {
                double g = g0;
                int it = 0;
                double res = 1;
                for (; it < 200 && res > 1e-13; ++it)
                {
                    const LinearizedNormalLaw lin = linearizeNormalLaw
                    (
                        barrierPressureExtended(g, dh, kappa, gE), g
                    );
                    const double gNew =
                        lin.coupled
                      ? (lin.pressure0 - k*(A - g0))/(k + 1/lin.compliance)
                      : (lin.pressure0 - k*(A - g0))/k;
                    res = std::abs(gNew - g)/dh;
                    g = gNew;
                }
                EXPECT_LT(it, 200) << "k " << k << " g0 " << g0 << " A " << A;
                if (A < g0 - dh)
                {
                    EXPECT_NEAR(g, g0 - A, 1e-12*g0);
                }
                else
                {
                    // The extended law's root: the barrier's where the
                    // column's pressure at gE is below the law's there
                    // (both monotone in g); only the stiffest column
                    // pushed furthest (k A = 1e8 Pa against about
                    // kappa dhat^2/gE = 1e7 Pa) ends on the extension,
                    // where the method doubles kappa
                    const double p =
                        barrierPressureExtended(g, dh, kappa, gE).pressure;
                    EXPECT_LT(g, dh);
                    EXPECT_NEAR(p, k*(A - g0 + g), 1e-9*p) << "k " << k << " g0 " << g0;
                    const bool onBarrier =
                        k*(A - g0 + gE) < barrierPressure(gE, dh, kappa).pressure;
                    EXPECT_EQ(g > gE, onBarrier) << "k " << k << " g0 " << g0 << " A " << A;
                    EXPECT_EQ(onBarrier, !(k == 1e9 && A == 1e-1));
                }
            }
        }
    }
}
