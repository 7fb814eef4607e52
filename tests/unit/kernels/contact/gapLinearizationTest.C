// Unit tests of the gap's linearisation in finite deformation,
// src/kernels/contact/gapLinearization: the gap, its gradient and Hessian
// in the four points and the projection's coordinates, each against
// central differences over random configurations (above, penetrating, on
// the plane, projecting outside the triangle, slivers), the gradient
// against normalGap's shape-function form, and degenerate input.

#include "gapLinearization.H"
#include "normalGap.H"
#include "../fpeTraps.H"

#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include <random>

using namespace c4f::contact;
using V = Eigen::Vector3d;
using X12 = Eigen::Matrix<double, 12, 1>;

namespace
{

GapLinearization at(const X12& X)
{
    return linearizeTriangleGap
    (
        X.segment<3>(0), X.segment<3>(3), X.segment<3>(6), X.segment<3>(9)
    );
}

X12 pack(const V& x2, const V& a, const V& b, const V& c)
{
    X12 X;
    X << x2, a, b, c;
    return X;
}

// Configurations of the sweep: a random triangle (scale L, sliver
// aspect s) and a point at height z over a point with local coordinates
// (u, v) (outside the triangle for u + v > 1 or a negative one)
X12 configuration(std::mt19937& rng, const double L, const double s, const double z,
                  const double u, const double v)
{
    std::uniform_real_distribution<double> U(-1, 1);
    const V a(L*V(U(rng), U(rng), U(rng)));
    const V e1(L*V(1 + 0.3*U(rng), 0.3*U(rng), 0.3*U(rng)));
    const V e2(L*s*V(0.3*U(rng), 1 + 0.3*U(rng), 0.3*U(rng)));
    const V n(e1.cross(e2).normalized());
    return pack(a + u*e1 + v*e2 + z*L*n, a, a + e1, a + e2);
}

} // End anonymous namespace


TEST(gapLinearization, gapNormalAndCoordinatesOfAKnownTriangle)
{
    const GapLinearization L =
        linearizeTriangleGap(V(0.2, 0.3, 0.05), V(0, 0, 0), V(1, 0, 0), V(0, 1, 0));
    ASSERT_TRUE(L.valid);
    EXPECT_NEAR(L.gap, 0.05, 1e-15);
    EXPECT_NEAR((L.normal - V(0, 0, 1)).norm(), 0, 1e-15);
    EXPECT_NEAR(L.xi(0), 0.2, 1e-15);
    EXPECT_NEAR(L.xi(1), 0.3, 1e-15);
    // Moving x2 along the normal changes g one for one and xi not at all
    EXPECT_NEAR(L.gradient(2), 1.0, 1e-15);
    EXPECT_NEAR(L.xiGradient.col(2).norm(), 0, 1e-15);
    // A rigid translation of all four points changes nothing: the
    // gradient's blocks sum to zero, and the Hessian maps a translation to
    // zero
    for (int d = 0; d < 3; ++d)
    {
        EXPECT_NEAR(L.gradient(d) + L.gradient(3 + d) + L.gradient(6 + d)
                  + L.gradient(9 + d), 0, 1e-15);
        X12 shift(X12::Zero());
        for (int node = 0; node < 4; ++node)
        {
            shift(3*node + d) = 1;
        }
        EXPECT_NEAR((L.hessian*shift).norm(), 0, 1e-14) << d;
    }
}

TEST(gapLinearization, gradientIsTheShapeFunctionForm)
{
    // The normal's variation does not enter delta g_N: the gradient equals
    // normalGap's (x2 - sum N_i x_i).n, also for a point outside
    std::mt19937 rng(7);
    for (int k = 0; k < 50; ++k)
    {
        const X12 X = configuration(rng, 1.0, 1.0, 0.3*(k % 5 - 2), 0.1*(k % 13) - 0.2,
                                    0.07*(k % 11) - 0.1);
        const GapLinearization L = at(X);
        ASSERT_TRUE(L.valid);
        const TriangleProjection p = projectOntoTriangle
        (
            X.segment<3>(0), X.segment<3>(3), X.segment<3>(6), X.segment<3>(9)
        );
        const Eigen::Matrix<double, 3, 4> G = gapGradient(p);
        EXPECT_NEAR(L.gap, p.gap, 1e-14);
        for (int node = 0; node < 4; ++node)
        {
            EXPECT_NEAR((L.gradient.segment<3>(3*node) - G.col(node)).norm(), 0, 1e-13)
                << "configuration " << k << " node " << node;
        }
        EXPECT_NEAR(L.xi(0), p.shape(1), 1e-13);
        EXPECT_NEAR(L.xi(1), p.shape(2), 1e-13);
    }
}

TEST(gapLinearization, derivativesMatchCentralDifferences)
{
    // Over scales from 1e-3 to 1e3, slivers of aspect 1e-2, points above,
    // below, on the plane and projecting outside: gradient against central
    // differences of the gap, the Hessian and d xi/dX against central
    // differences of the gradient and of xi, relative to their size
    std::mt19937 rng(42);
    // Tolerance: central differences at h = 1e-6 L truncate by about
    // (h/(s L))^2 (the sliver's short side s L), round-off about 1e-16/1e-6;
    // 1e-9/s^2 covers both with a margin (measured 1e-10 at s = 1, 1.5e-7
    // at s = 1e-2, the worst of the gradient, Hessian and d xi/dX)
    int n = 0;
    for (const double L0 : {1e-3, 1.0, 1e3})
    {
        for (const double s : {1.0, 0.1, 1e-2})
        {
            const double tol = 1e-9/(s*s);
            for (const double z : {0.5, 1e-3, 0.0, -0.2})
            {
                for (const double u : {0.2, 0.9, -0.5})
                {
                    const X12 X = configuration(rng, L0, s, z, u, 0.25);
                    const GapLinearization L = at(X);
                    ASSERT_TRUE(L.valid);
                    const double h = 1e-6*L0;
                    X12 fdG;
                    Eigen::Matrix<double, 12, 12> fdH;
                    Eigen::Matrix<double, 2, 12> fdXi;
                    for (int i = 0; i < 12; ++i)
                    {
                        X12 Xp(X), Xm(X);
                        Xp(i) += h;
                        Xm(i) -= h;
                        const GapLinearization P = at(Xp), M = at(Xm);
                        fdG(i) = (P.gap - M.gap)/(2*h);
                        fdH.col(i) = (P.gradient - M.gradient)/(2*h);
                        fdXi.col(i) = (P.xi - M.xi)/(2*h);
                    }
                    const double scaleH = std::max(L.hessian.norm(), 1/L0);
                    EXPECT_LT((fdG - L.gradient).norm()/L.gradient.norm(), tol)
                        << "L " << L0 << " s " << s << " z " << z << " u " << u;
                    EXPECT_LT((fdH - L.hessian).norm()/scaleH, tol)
                        << "L " << L0 << " s " << s << " z " << z << " u " << u;
                    EXPECT_LT((fdXi - L.xiGradient).norm()/L.xiGradient.norm(), tol)
                        << "L " << L0 << " s " << s << " z " << z << " u " << u;
                    // Assembled row by row, symmetric to round-off
                    EXPECT_LT((L.hessian - L.hessian.transpose()).norm()/scaleH, 1e-12)
                        << "L " << L0 << " s " << s << " z " << z << " u " << u;
                    ++n;
                }
            }
        }
    }
    EXPECT_EQ(n, 108);
}

TEST(gapLinearization, hessianOfAFlatSupportIsItsRotation)
{
    // x2 on the plane over the centroid: a rigid rotation of the triangle
    // about an axis in its plane through x2 leaves g = 0 to first order,
    // and the Hessian of g in that rotation is zero too, since x2 stays
    // on the turned plane to second order (it lies on the axis). A point
    // at height z over the axis: g = z cos(theta), d2g/dtheta2 = -z
    const V a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    const V centroid((a + b + c)/3);
    for (const double z : {0.0, 0.2, -0.1})
    {
        const X12 X = pack(centroid + V(0, 0, z), a, b, c);
        const GapLinearization L = at(X);
        // the rotation about the x axis through the centroid, applied to
        // the triangle only: dX/dtheta = w x (x_i - centroid), w = e_x,
        // and its second derivative w x (w x (x_i - centroid))
        X12 d1(X12::Zero()), d2(X12::Zero());
        for (int node = 1; node < 4; ++node)
        {
            const V arm(X.segment<3>(3*node) - centroid);
            d1.segment<3>(3*node) = V(1, 0, 0).cross(arm);
            d2.segment<3>(3*node) = V(1, 0, 0).cross(V(1, 0, 0).cross(arm));
        }
        const double first = L.gradient.dot(d1);
        const double second = d1.dot(L.hessian*d1) + L.gradient.dot(d2);
        // Turning the triangle by theta about that axis: the plane's
        // distance to x2 is z cos(theta)
        EXPECT_NEAR(first, 0.0, 1e-14) << z;
        EXPECT_NEAR(second, -z, 1e-13) << z;
    }
}

TEST(gapLinearization, degenerateInputIsReportedNotDivided)
{
    const double NaN = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    // Zero area: coincident points, collinear points
    for (const X12& X :
        {
            pack(V(0, 0, 1), V(0, 0, 0), V(0, 0, 0), V(0, 1, 0)),
            pack(V(0, 0, 1), V(0, 0, 0), V(1, 0, 0), V(2, 0, 0)),
            pack(V(0, 0, 1), V(0, 0, 0), V(0, 0, 0), V(0, 0, 0)),
            pack(V(NaN, 0, 1), V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)),
            pack(V(0, 0, 1), V(0, inf, 0), V(1, 0, 0), V(0, 1, 0))
        })
    {
        const GapLinearization L = at(X);
        EXPECT_FALSE(L.valid);
        EXPECT_EQ(L.gap, 0.0);
        EXPECT_TRUE(L.gradient.allFinite());
        EXPECT_TRUE(L.hessian.allFinite());
        EXPECT_TRUE(L.xiGradient.allFinite());
        EXPECT_EQ(L.hessian.norm(), 0.0);
    }
    // A sliver of aspect 1e-8 is still a triangle: finite everything, and
    // the projection's coordinates right (by the metric's inverse they
    // were (0.25, 0), and NaN for thinner ones)
    const GapLinearization L =
        at(pack(V(0.3, 1e-9, 0.1), V(0, 0, 0), V(1, 0, 0), V(0.5, 1e-8, 0)));
    EXPECT_TRUE(L.valid);
    EXPECT_TRUE(L.hessian.allFinite());
    EXPECT_TRUE(L.xiGradient.allFinite());
    EXPECT_NEAR(L.gap, 0.1, 1e-12);
    EXPECT_NEAR(L.xi(0), 0.25, 1e-12);
    EXPECT_NEAR(L.xi(1), 0.1, 1e-12);
}

TEST(gapLinearization, sliversKeepTheirCoordinates)
{
    // Angles from 1e-6 down to 1e-13 rad, with the traps OpenFOAM's
    // FOAM_SIGFPE sets: x2 over the point with xi = (0.4, 0.3)
    const FpeTraps traps(FE_OVERFLOW | FE_DIVBYZERO | FE_INVALID);
    for (const double s : {1e-6, 1e-8, 1e-10, 1e-13})
    {
        const GapLinearization L = linearizeTriangleGap
        (
            V(0.7, 0.3*s, 0.1), V(0, 0, 0), V(1, 0, 0), V(1, s, 0)
        );
        EXPECT_TRUE(L.valid) << s;
        EXPECT_NEAR(L.xi(0), 0.4, 1e-12) << s;
        EXPECT_NEAR(L.xi(1), 0.3, 1e-12) << s;
        EXPECT_NEAR(L.gap, 0.1, 1e-15) << s;
        EXPECT_TRUE(L.xiGradient.allFinite()) << s;
        EXPECT_TRUE(L.hessian.allFinite()) << s;
    }
}
