// Unit tests of the face interpolation kernel,
// src/kernels/transfer/polygonInterpolation (mean value coordinates).
// Checked: a partition of unity that reproduces linear functions on
// triangles, quads and pentagons in any orientation; barycentric
// coordinates on a triangle; the vertex and edge cases; continuity across
// the edge two faces share (the property the smoothed contact normal
// needs), also on the deep, narrow faces of a one-cell-thick 2D mesh,
// where an inverse-distance blend is not continuous; and degenerate
// polygons.

#include "polygonInterpolation.H"

#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace c4f::transfer;
using V = Eigen::Vector3d;

namespace
{

const double pi = 3.14159265358979323846;

Polygon moved(const Polygon& p, const Eigen::Matrix3d& R, const V& t)
{
    Polygon q;
    for (const V& x : p)
    {
        q.push_back(R*x + t);
    }
    return q;
}

Eigen::Matrix3d rotation(double a, const V& axis)
{
    return Eigen::AngleAxisd(a, axis.normalized()).toRotationMatrix();
}

V interpolate(const Polygon& p, const std::vector<double>& w)
{
    V x(V::Zero());
    for (size_t i = 0; i < p.size(); ++i)
    {
        x += w[i]*p[i];
    }
    return x;
}

double sum(const std::vector<double>& w)
{
    double s = 0;
    for (const double wi : w)
    {
        s += wi;
    }
    return s;
}

//- A regular n-gon of radius r about the origin in the z = 0 plane
Polygon regular(int n, double r)
{
    Polygon p;
    for (int i = 0; i < n; ++i)
    {
        p.push_back(V(r*std::cos(2*pi*i/n), r*std::sin(2*pi*i/n), 0));
    }
    return p;
}

} // End anonymous namespace


TEST(polygonInterpolation, partitionOfUnityAndLinearPrecision)
{
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-1, 1);
    const std::vector<Polygon> shapes
    {
        {V(0, 0, 0), V(1, 0, 0), V(0.2, 0.9, 0)},
        {V(0, 0, 0), V(2, 0, 0), V(2.3, 1, 0), V(-0.1, 0.8, 0)},
        regular(5, 1.5),
        regular(6, 0.01)
    };
    for (const Polygon& shape : shapes)
    {
        for (int k = 0; k < 20; ++k)
        {
            const Eigen::Matrix3d R(rotation(pi*u(gen), V(u(gen), u(gen), u(gen))));
            const V t(u(gen), u(gen), u(gen));
            const Polygon p(moved(shape, R, t));
            // A point inside: a random convex combination of the vertices
            std::vector<double> c(p.size());
            for (double& ci : c)
            {
                ci = 0.1 + std::abs(u(gen));
            }
            const double s = sum(c);
            for (double& ci : c)
            {
                ci /= s;
            }
            const V x(interpolate(p, c));
            const std::vector<double> w(meanValueCoordinates(p, x));
            ASSERT_EQ(w.size(), p.size());
            const double size = (p[1] - p[0]).norm();
            EXPECT_NEAR(sum(w), 1, 1e-12);
            EXPECT_LT((interpolate(p, w) - x).norm(), 1e-11*size);
            for (const double wi : w)
            {
                // Positive inside a convex polygon
                EXPECT_GT(wi, 0);
            }
        }
    }
}


TEST(polygonInterpolation, triangleIsBarycentric)
{
    const Polygon p{V(0, 0, 1), V(2, 0, 1), V(0, 3, 1)};
    const V x(0.5, 0.75, 1);
    const std::vector<double> w(meanValueCoordinates(p, x));
    // Barycentric: areas of the opposite sub-triangles
    EXPECT_NEAR(w[1], 0.25, 1e-13);
    EXPECT_NEAR(w[2], 0.25, 1e-13);
    EXPECT_NEAR(w[0], 0.5, 1e-13);
}


TEST(polygonInterpolation, vertexAndEdge)
{
    const Polygon p{V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0)};
    for (size_t i = 0; i < p.size(); ++i)
    {
        const std::vector<double> w(meanValueCoordinates(p, p[i]));
        for (size_t j = 0; j < p.size(); ++j)
        {
            EXPECT_NEAR(w[j], i == j ? 1 : 0, 1e-12);
        }
    }
    // On the edge from vertex 1 to 2 at 30 %: linear between those two
    const std::vector<double> w(meanValueCoordinates(p, V(1, 0.3, 0)));
    EXPECT_NEAR(w[1], 0.7, 1e-12);
    EXPECT_NEAR(w[2], 0.3, 1e-12);
    EXPECT_NEAR(w[0], 0, 1e-12);
    EXPECT_NEAR(w[3], 0, 1e-12);
}


TEST(polygonInterpolation, continuousAcrossASharedEdge)
{
    // Two faces of a faceted arc on a one-cell-thick 2D mesh: 0.058 wide,
    // 1 deep, sharing the edge at x = 0 (points 1 and 2 of a, 0 and 3 of
    // b), with a kink between them. A point normal is attached to each
    // point; the interpolated normal just either side of the edge must
    // agree
    const double h = 0.058, dz = 1, kink = 4.4*pi/180;
    const Polygon a{V(-h, 0, 0), V(0, 0, 0), V(0, 0, dz), V(-h, 0, dz)};
    const V tb(h*std::cos(kink), -h*std::sin(kink), 0);
    const Polygon b{V(0, 0, 0), tb, tb + V(0, 0, dz), V(0, 0, dz)};
    const V nA(0, 1, 0), nEdge(std::sin(kink/2), std::cos(kink/2), 0);
    const V nB(std::sin(kink), std::cos(kink), 0);
    const std::vector<V> na{nA, nEdge, nEdge, nA};
    const std::vector<V> nb{nEdge, nB, nB, nEdge};
    const auto normal = [](const std::vector<double>& w, const std::vector<V>& n)
    {
        V s(V::Zero());
        for (size_t i = 0; i < n.size(); ++i)
        {
            s += w[i]*n[i];
        }
        return V(s.normalized());
    };
    for (const double z : {0.0, 0.1, 0.5, 0.97, 1.0})
    {
        const double eps = 1e-9*h;
        const V xa(-eps, 0, z);
        const V xb(tb.normalized()*eps + V(0, 0, z));
        const V na_(normal(meanValueCoordinates(a, xa), na));
        const V nb_(normal(meanValueCoordinates(b, xb), nb));
        EXPECT_LT((na_ - nEdge).norm(), 1e-7) << "z = " << z;
        EXPECT_LT((nb_ - nEdge).norm(), 1e-7) << "z = " << z;
    }
    // Across the face the normal turns from the edge's to the other
    // edge's linearly in the weights: half way it is the two edges' mean
    const V mid(normal(meanValueCoordinates(a, V(-h/2, 0, 0.5)), na));
    EXPECT_LT((mid - V(nA + nEdge).normalized()).norm(), 1e-9);
}


TEST(polygonInterpolation, slightlyOffThePolygon)
{
    // A projection just outside the face (round-off) or off its plane:
    // still a partition of unity reproducing the in-plane point
    const Polygon p{V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0)};
    for (const V& x : {V(1 + 1e-14, 0.5, 0), V(0.3, -1e-13, 0), V(0.4, 0.6, 1e-3)})
    {
        const std::vector<double> w(meanValueCoordinates(p, x));
        EXPECT_NEAR(sum(w), 1, 1e-12);
        const V y(interpolate(p, w));
        EXPECT_LT((y - V(x.x(), x.y(), 0)).norm(), 1e-10);
    }
}


TEST(polygonInterpolation, degenerate)
{
    // Empty, one or two points, all collinear: the nearest vertex
    EXPECT_TRUE(meanValueCoordinates({}, V(0, 0, 0)).empty());
    const std::vector<double> w1(meanValueCoordinates({V(1, 2, 3)}, V(0, 0, 0)));
    ASSERT_EQ(w1.size(), 1u);
    EXPECT_EQ(w1[0], 1);
    const Polygon line{V(0, 0, 0), V(1, 0, 0), V(2, 0, 0)};
    const std::vector<double> w(meanValueCoordinates(line, V(1.9, 0.1, 0)));
    ASSERT_EQ(w.size(), 3u);
    EXPECT_EQ(w[2], 1);
    EXPECT_EQ(w[0] + w[1], 0);
    // A vanishing sliver: finite weights summing to one
    const Polygon sliver{V(0, 0, 0), V(1, 0, 0), V(1, 1e-300, 0), V(0, 1e-300, 0)};
    const std::vector<double> ws(meanValueCoordinates(sliver, V(0.5, 0, 0)));
    EXPECT_NEAR(sum(ws), 1, 1e-12);
    for (const double wi : ws)
    {
        EXPECT_TRUE(std::isfinite(wi));
    }
}


TEST(polygonInterpolation, repeatedVertexAndSelfCrossing)
{
    // A vertex repeated (points merged within a tolerance): CGAL's
    // precondition (a simple polygon) would throw; the repeat takes no
    // weight and the rest are the triangle's barycentric coordinates
    const Polygon rep{V(0, 0, 0), V(1, 0, 0), V(1, 0, 0), V(0, 1, 0)};
    const std::vector<double> w(meanValueCoordinates(rep, V(0.2, 0.3, 0)));
    ASSERT_EQ(w.size(), 4u);
    EXPECT_NEAR(w[0], 0.5, 1e-12);
    EXPECT_NEAR(w[1] + w[2], 0.2, 1e-12);
    EXPECT_EQ(w[1]*w[2], 0);
    EXPECT_NEAR(w[3], 0.3, 1e-12);
    // The first point repeated at the end
    const Polygon wrap{V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, 0)};
    const std::vector<double> ww(meanValueCoordinates(wrap, V(0.2, 0.3, 0)));
    ASSERT_EQ(ww.size(), 4u);
    EXPECT_NEAR(ww[0] + ww[3], 0.5, 1e-12);
    EXPECT_NEAR(ww[1], 0.2, 1e-12);
    EXPECT_NEAR(ww[2], 0.3, 1e-12);
    // A self-crossing quad with area: the nearest vertex, not an exception
    const Polygon bow{V(0, 0, 0), V(2, 0, 0), V(0, 1, 0), V(1, 1, 0)};
    const std::vector<double> wb(meanValueCoordinates(bow, V(1.9, 0.1, 0)));
    ASSERT_EQ(wb.size(), 4u);
    EXPECT_EQ(wb[1], 1);
    EXPECT_NEAR(sum(wb), 1, 1e-12);
}
