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

TEST(planeGap, parallelPlanesTiltedSlaveAndLinearity)
{
    const V nm(0, 0, 1), xm(0.3, -0.1, 1.0);

    // Parallel planes: the distance, wherever c lies and whichever way
    // the slave normal points
    const V xs(2.0, 5.0, 1.25);
    for (const V& c : {V(0, 0, 0), V(0.7, 0.2, 1.0), V(-3, 4, 9)})
    {
        EXPECT_NEAR(planeGap(c, xm, nm, xs, V(0, 0, -1)), 0.25, 1e-15);
        EXPECT_NEAR(planeGap(c, xm, nm, xs, V(0, 0, 3)), 0.25, 1e-15);
    }

    // A slave plane tilted by slope s along x: its height over c is
    // z(xs) + s (c.x - xs.x)
    const double s = 0.03;
    const V ns(-s, 0, 1);
    const V c(0.5, 0.0, 1.0);
    const V xs2(0.2, 0.0, 1.001);
    EXPECT_NEAR(planeGap(c, xm, nm, xs2, ns), 0.001 + s*(0.5 - 0.2), 1e-15);
    // The slave plane's point over c lies on it and above c along nm
    const double g = planeGap(c, xm, nm, xs2, ns);
    const V y = c + (g - nm.dot(c - xm))*nm;
    EXPECT_NEAR(ns.dot(y - xs2), 0, 1e-15);

    // Linear in xs and xm with dg/dxs = ns/(ns.nm), dg/dxm = -nm
    const V nsTilted(0.1, -0.2, -1.0), nmTilted = V(0.05, 0.02, 1.0).normalized();
    const V d1(1e-3, -2e-3, 3e-3), d2(-4e-3, 1e-3, 2e-3);
    const double g0 = planeGap(c, xm, nmTilted, xs2, nsTilted);
    EXPECT_NEAR(planeGap(c, xm, nmTilted, xs2 + d1, nsTilted) - g0,
                nsTilted.dot(d1)/nsTilted.dot(nmTilted), 1e-15);
    EXPECT_NEAR(planeGap(c, xm + d2, nmTilted, xs2, nsTilted) - g0,
                -nmTilted.dot(d2), 1e-15);

    // Edge-on slave: the centres' distance, finite
    EXPECT_NEAR(planeGap(c, xm, nm, xs, V(1, 0, 0)), 0.25, 1e-15);
}
