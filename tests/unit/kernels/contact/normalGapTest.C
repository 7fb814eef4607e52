// Unit tests of the normal gap and projection kernel,
// src/kernels/contact/normalGap. The gap gradient is checked against
// central differences of the full projection, including the rotation of
// the master normal with its vertices.

#include "normalGap.H"

#include <gtest/gtest.h>
#include <cmath>

using namespace c4f::contact;
using V = Eigen::Vector3d;

TEST(normalGap, pointAboveFlatTriangle)
{
    const V a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    const TriangleProjection p = projectOntoTriangle(V(0.2, 0.3, 0.05), a, b, c);
    EXPECT_NEAR(p.gap, 0.05, 1e-15);
    EXPECT_NEAR((p.normal - V(0, 0, 1)).norm(), 0, 1e-15);
    EXPECT_NEAR((p.point - V(0.2, 0.3, 0)).norm(), 0, 1e-15);
    EXPECT_NEAR(p.shape.sum(), 1.0, 1e-15);
    EXPECT_NEAR(p.shape(1), 0.2, 1e-15);
    EXPECT_NEAR(p.shape(2), 0.3, 1e-15);
    EXPECT_TRUE(p.inside);
}

TEST(normalGap, penetrationIsNegativeAndOutsideIsFlagged)
{
    const V a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    EXPECT_NEAR(projectOntoTriangle(V(0.1, 0.1, -2e-3), a, b, c).gap, -2e-3, 1e-16);
    EXPECT_FALSE(projectOntoTriangle(V(0.8, 0.8, 0.1), a, b, c).inside);
    EXPECT_FALSE(projectOntoTriangle(V(-0.01, 0.5, 0.1), a, b, c).inside);
    // On a shared edge a point is inside (both neighbours accept it)
    EXPECT_TRUE(projectOntoTriangle(V(0.5, 0.5, 0.1), a, b, c).inside);
}

TEST(normalGap, shapeFunctionsReproduceTheProjection)
{
    const V a(0.3, -0.2, 1.0), b(1.4, 0.1, 0.7), c(0.2, 1.1, 1.3);
    const V x(0.6, 0.4, 2.0);
    const TriangleProjection p = projectOntoTriangle(x, a, b, c);
    const V rebuilt = p.shape(0)*a + p.shape(1)*b + p.shape(2)*c;
    EXPECT_NEAR((rebuilt - p.point).norm(), 0, 1e-14);
    // The projection direction is the normal
    EXPECT_NEAR(((x - p.point).cross(p.normal)).norm(), 0, 1e-14);
    EXPECT_NEAR(normalGap(x, p.point, p.normal), p.gap, 1e-15);
}

TEST(normalGap, gradientMatchesCentralDifferencesIncludingNormalRotation)
{
    V X[4] = {V(0.6, 0.4, 1.4), V(0.3, -0.2, 1.0), V(1.4, 0.1, 0.7), V(0.2, 1.1, 1.3)};
    const TriangleProjection p0 = projectOntoTriangle(X[0], X[1], X[2], X[3]);
    ASSERT_TRUE(p0.inside);
    const Eigen::Matrix<double, 3, 4> G = gapGradient(p0);

    const double h = 1e-6;
    double maxErr = 0;
    for (int node = 0; node < 4; ++node)
    {
        for (int d = 0; d < 3; ++d)
        {
            V Xp[4] = {X[0], X[1], X[2], X[3]};
            V Xm[4] = {X[0], X[1], X[2], X[3]};
            Xp[node](d) += h;
            Xm[node](d) -= h;
            const double gp = projectOntoTriangle(Xp[0], Xp[1], Xp[2], Xp[3]).gap;
            const double gm = projectOntoTriangle(Xm[0], Xm[1], Xm[2], Xm[3]).gap;
            maxErr = std::max(maxErr, std::abs((gp - gm)/(2*h) - G(d, node)));
        }
    }
    // Exact gradient of a smooth function: central differences agree to
    // O(h^2) ~ 1e-12 times the curvature, plus round-off ~1e-16/h
    EXPECT_LT(maxErr, 1e-8);
}

TEST(normalGap, degenerateSweepHasRightSignAndNoNaN)
{
    for (const double scale : {1e-6, 1e-3, 1.0, 1e3})
    {
        const V a = scale*V(0, 0, 0), b = scale*V(1, 0.1, 0), c = scale*V(0.2, 1, 0.05);
        const TriangleProjection q = projectOntoTriangle(scale*V(0.3, 0.3, 0.1), a, b, c);
        for (const double g : {-1e-12, 0.0, 1e-12})
        {
            const V x = q.point + g*scale*q.normal;
            const TriangleProjection p = projectOntoTriangle(x, a, b, c);
            EXPECT_TRUE(std::isfinite(p.gap));
            EXPECT_TRUE(p.shape.allFinite());
            EXPECT_NEAR(p.gap, g*scale, 1e-15*scale + 1e-22);
        }
    }
}
