// Unit tests of the constitutive (power-law) interface law,
// src/kernels/contact/constitutiveContactLaw.
// Reference: Wriggers, Computational Contact Mechanics (2nd ed. 2006),
// ch. 6, chapter eq. 2.20-2.21. The slope is checked against central
// differences with a tolerance built from the step; n = 1 must be the
// penalty law bit for bit; the sublinear law's unbounded slope must stay
// finite; no input may raise a floating-point exception.

#include "constitutiveContactLaw.H"

#include <gtest/gtest.h>
#include <cfenv>
#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

using namespace c4f::contact;

TEST(constitutiveContactLaw, powerOfPenetration)
{
    // n = 2 with c_N = 1e18 Pa/m^2: 1 MPa at 1 um
    const NormalLawValue v = constitutivePressure(-1e-6, 1e18, 2.0);
    EXPECT_DOUBLE_EQ(v.pressure, 1e6);
    EXPECT_DOUBLE_EQ(v.dPressureDGap, -2e12);

    const double cN = 3e25, n = 3.33, x = 2e-6;
    const NormalLawValue w = constitutivePressure(-x, cN, n);
    EXPECT_DOUBLE_EQ(w.pressure, cN*std::pow(x, n));
    EXPECT_DOUBLE_EQ(w.dPressureDGap, -n*cN*std::pow(x, n - 1));

    for (const double g : {0.0, -0.0, 1e-300, 1e-6, 1.0})
    {
        EXPECT_EQ(constitutivePressure(g, cN, n).pressure, 0.0);
        EXPECT_EQ(constitutivePressure(g, cN, n).dPressureDGap, 0.0);
    }
}

TEST(constitutiveContactLaw, linearLawIsPenaltyExactly)
{
    for (const double cN : {1e-200, 1e-3, 1.0, 3.7e9, 2.69e14, 1e200})
    {
        for (const double g :
            {-1e3, -1.0, -1e-6, -1e-12, -1e-300, -0.0, 0.0, 1e-300, 1e-6, 1.0})
        {
            const NormalLawValue a = constitutivePressure(g, cN, 1.0);
            const NormalLawValue b = penaltyPressure(g, cN);
            EXPECT_EQ(a.pressure, b.pressure) << "cN = " << cN << ", g = " << g;
            EXPECT_EQ(a.dPressureDGap, b.dPressureDGap) << "cN = " << cN << ", g = " << g;
        }
    }
}

TEST(constitutiveContactLaw, derivativeMatchesCentralDifferences)
{
    const double cN = 1e18;
    for (const double n : {0.5, 0.9, 1.0, 1.5, 2.0, 2.5, 3.33})
    {
        for (const double g : {-1e-3, -1e-5, -3e-7, -1e-8, 1e-8, 1e-5})
        {
            // Relative step, so that g +- h never crosses the kink at 0
            const double h = 1e-4*std::abs(g);
            const double pPlus = constitutivePressure(g + h, cN, n).pressure;
            const double pMinus = constitutivePressure(g - h, cN, n).pressure;
            const double fd = (pPlus - pMinus)/(2*h);

            // Truncation h^2/6 max|p'''| on [g - h, g + h], with
            // |p'''| = c_N |n (n-1) (n-2)| x^(n-3), x = -g (largest at
            // x - h for n < 3, at x + h above); rounding a few ulp of
            // each value and of g +- h times the slope, over 2h
            double tol = 0;
            const double slope = constitutivePressure(g, cN, n).dPressureDGap;
            if (g < 0)
            {
                const double x = -g;
                const double xFar = n < 3 ? x - h : x + h;
                tol =
                    h*h/6*cN*std::abs(n*(n - 1)*(n - 2))*std::pow(xFar, n - 3)
                  + 4*DBL_EPSILON*(std::max(pPlus, pMinus) + std::abs(slope)*(x + h))/(2*h);
            }
            EXPECT_NEAR(slope, fd, tol) << "n = " << n << ", g = " << g;
        }
    }
}

TEST(constitutiveContactLaw, sublinearSlopeUnboundedButFinite)
{
    // n = 0.5: dp/dg = -0.5 c_N (-g)^(-1/2) grows without bound as
    // g -> 0-, and every value at a negative gap is exact and finite
    const double cN = 1e9, n = 0.5;
    double previous = 0;
    for (int k = 3; k <= 300; k += 3)
    {
        const double g = -std::pow(10.0, -k);
        const NormalLawValue v = constitutivePressure(g, cN, n);
        EXPECT_TRUE(std::isfinite(v.dPressureDGap)) << g;
        EXPECT_LT(v.dPressureDGap, previous) << g;
        EXPECT_NEAR(v.dPressureDGap, -n*cN/std::sqrt(-g), 8*DBL_EPSILON*n*cN/std::sqrt(-g)) << g;
        previous = v.dPressureDGap;
    }
    // At the gap itself there is no contact
    EXPECT_EQ(constitutivePressure(0.0, cN, n).dPressureDGap, 0.0);

    // Where the exact slope exceeds the largest double it saturates there
    // (n = 1e-3, c_N = 1e20, g = -1e-300: about 1e17 x 1e299.7)
    const NormalLawValue s = constitutivePressure(-1e-300, 1e20, 1e-3);
    EXPECT_EQ(s.dPressureDGap, -DBL_MAX);
    EXPECT_NEAR(s.pressure, 1e20*std::pow(1e-300, 1e-3), 1e-13*s.pressure);
}

TEST(constitutiveContactLaw, degenerateInputsRaiseNoException)
{
    std::vector<NormalLawValue> values;
    int raised = 0;
    for (const double cN : {1e-200, 1.0, 1e12, 1e18, 1e200})
    {
        for (const double n : {1e-3, 0.01, 0.5, 1.0, 2.0, 3.33, 10.0, 100.0})
        {
            for (const double g :
                {-1e3, -1.0, -1e-12, -1e-300, -0.0, 0.0, 1e-300, 1e-12, 1.0, 1e3})
            {
                std::feclearexcept(FE_ALL_EXCEPT);
                values.push_back(constitutivePressure(g, cN, n));
                // n = 1 is penaltyPressure's plain product, which may
                // underflow (1e-200 x 1e-300); every other n is built not to
                const int mask = n == 1
                    ? FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW
                    : FE_ALL_EXCEPT & ~FE_INEXACT;
                raised |= std::fetestexcept(mask);
            }
        }
    }
    EXPECT_EQ(raised, 0);
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        const NormalLawValue& v = values[i];
        EXPECT_TRUE(std::isfinite(v.pressure) && std::isfinite(v.dPressureDGap)) << i;
        EXPECT_GE(v.pressure, 0.0) << i;
        EXPECT_LE(v.dPressureDGap, 0.0) << i;
    }
}

TEST(constitutiveContactLaw, tinyResultsFlushToZero)
{
    // c_N (1e-300)^3.33 is about 1e-987: zero, not a subnormal or an
    // underflow; and a product whose factor x^n alone would underflow
    // but c_N lifts back into range keeps its value
    EXPECT_EQ(constitutivePressure(-1e-300, 1e12, 3.33).pressure, 0.0);
    const double cN = 1e250, n = 3.5, x = 1e-100;   // x^n = 1e-350, p = 1e-100
    EXPECT_NEAR(constitutivePressure(-x, cN, n).pressure, 1e-100, 1e-100*1e-12);
}

TEST(constitutiveContactLaw, validation)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(validConstitutiveLaw(1e18, 2.0));
    EXPECT_TRUE(validConstitutiveLaw(1.0, 0.5));
    EXPECT_FALSE(validConstitutiveLaw(0.0, 2.0));
    EXPECT_FALSE(validConstitutiveLaw(-1.0, 2.0));
    EXPECT_FALSE(validConstitutiveLaw(1.0, 0.0));
    EXPECT_FALSE(validConstitutiveLaw(1.0, -2.0));
    EXPECT_FALSE(validConstitutiveLaw(nan, 2.0));
    EXPECT_FALSE(validConstitutiveLaw(1.0, nan));
    EXPECT_FALSE(validConstitutiveLaw(inf, 2.0));
    EXPECT_FALSE(validConstitutiveLaw(1.0, inf));
    EXPECT_NE(describeConstitutiveLawRequirement().find("positive"), std::string::npos);
}

TEST(constitutiveContactLaw, gapForPressureInvertsTheLaw)
{
    // Round trip g -> p(g) -> g over the laws and penetrations of the
    // tutorials (stiff c_N 1e22 and soft 1e17 at n = 2, the 3D patch
    // test's 1e10) and a sublinear and a steep exponent
    for (const double cN : {1e10, 1e17, 1e22, 3e25})
    {
        for (const double n : {0.5, 1.0, 2.0, 3.33})
        {
            for (const double g : {-1e-2, -1e-5, -6e-7, -1e-9})
            {
                const double p = constitutivePressure(g, cN, n).pressure;
                if (!(p > 1e3*DBL_MIN && p < DBL_MAX))
                {
                    continue;
                }
                EXPECT_NEAR(constitutiveGapForPressure(p, cN, n), g, 1e-12*std::abs(g))
                    << "cN = " << cN << ", n = " << n << ", g = " << g;
            }
        }
    }
    // 1 MPa at 1 um for c_N = 1e18, n = 2
    EXPECT_DOUBLE_EQ(constitutiveGapForPressure(1e6, 1e18, 2.0), -1e-6);
}

TEST(constitutiveContactLaw, gapForPressureDegenerateInputs)
{
    std::feclearexcept(FE_ALL_EXCEPT);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const double p : {0.0, -0.0, -1.0, -inf, nan})
    {
        EXPECT_EQ(constitutiveGapForPressure(p, 1e22, 2.0), 0.0) << "p = " << p;
    }
    for (const double n : {0.5, 2.0, 3.33})
    {
        for (const double cN : {1e-300, 1.0, 1e300})
        {
            for (const double p : {DBL_MIN, 1e-300, 1.0, 1e300, DBL_MAX})
            {
                const double g = constitutiveGapForPressure(p, cN, n);
                EXPECT_TRUE(std::isfinite(g)) << p << " " << cN << " " << n;
                EXPECT_LE(g, 0.0);
            }
        }
    }
    EXPECT_FALSE(std::fetestexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW));
}
