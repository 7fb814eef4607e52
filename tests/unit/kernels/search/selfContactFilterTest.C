// Unit tests of the self-contact exclusions, src/kernels/search/
// selfContactFilter: the faces around a face's points (itself among them),
// faces that point the same way, the far side past a convex corner, and
// the one-pass choice of the slave of a pair, swept over orientations
// (every pair of opposed faces has a slave; outside the band exactly one).

#include "selfContactFilter.H"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace c4f::search;
using V = Eigen::Vector3d;

namespace
{

//- A strip of n quads along x, points 0..n on y = 0 and n+1..2n+1 on
//  y = 1: quad i is (i, i+1, n+2+i, n+1+i)
std::vector<std::vector<int>> strip(const int n)
{
    std::vector<std::vector<int>> faces;
    for (int i = 0; i < n; ++i)
    {
        faces.push_back({i, i + 1, n + 2 + i, n + 1 + i});
    }
    return faces;
}

} // End anonymous namespace


TEST(SelfContactFilter, facesAroundAFaceAreItselfAndItsNeighbours)
{
    const SelfContactFilter f(strip(5));
    // Quad 2's points: 2, 3, 9, 8
    EXPECT_EQ(f.facesAround({2, 3, 9, 8}), (std::vector<int>{1, 2, 3}));
    // An end quad has one neighbour
    EXPECT_EQ(f.facesAround({0, 1, 7, 6}), (std::vector<int>{0, 1}));
    // A corner point alone: the faces around it only
    EXPECT_EQ(f.facesAround({3}), (std::vector<int>{2, 3}));
}


TEST(SelfContactFilter, unknownPointsAreIgnored)
{
    const SelfContactFilter f(strip(3));
    EXPECT_TRUE(f.facesAround({-1, 100}).empty());
    EXPECT_EQ(f.facesAround({-1, 0}), (std::vector<int>{0}));
    const SelfContactFilter empty(std::vector<std::vector<int>>{});
    EXPECT_TRUE(empty.facesAround({0, 1}).empty());
}


TEST(SelfContactFilter, neighboursAndSameWayFacesAreExcluded)
{
    const std::vector<int> around{1, 2, 3};
    const V up(0, 0, 1), down(0, 0, -1), side(1, 0, 0);
    // A neighbour is excluded whatever its normal
    EXPECT_TRUE(SelfContactFilter::excluded(around, up, 2, down));
    EXPECT_TRUE(SelfContactFilter::excluded(around, up, 3, down));
    // Not a neighbour: only a face pointing the same way
    EXPECT_TRUE(SelfContactFilter::excluded(around, up, 7, up));
    EXPECT_TRUE(SelfContactFilter::excluded(around, up, 7, V(0.1, 0, 0.995)));
    EXPECT_FALSE(SelfContactFilter::excluded(around, up, 7, down));
    // At right angles (a slot's end and its sides) still a pair
    EXPECT_FALSE(SelfContactFilter::excluded(around, up, 7, side));
    EXPECT_FALSE(SelfContactFilter::excluded({}, up, 0, down));
}


TEST(SelfContactFilter, farSidePastAConvexCornerIsNoPenetration)
{
    // A beam's underside (normal -y) and its end (normal +x): the end's
    // faces lie behind the underside's centre
    const V underside(0, -1, 0), end(1, 0, 0);
    EXPECT_TRUE(SelfContactFilter::behindUnfaced(underside, end, -5e-4));
    EXPECT_FALSE(SelfContactFilter::behindUnfaced(underside, end, 5e-4));
    // A face pressed into one that faces it is a penetration
    const V floor(0, 1, 0);
    EXPECT_FALSE(SelfContactFilter::behindUnfaced(underside, floor, -1e-6));
    // Tilted by 30 degrees: still facing
    const double c = std::cos(M_PI/6), s = std::sin(M_PI/6);
    EXPECT_FALSE(SelfContactFilter::behindUnfaced(underside, V(s, c, 0), -1e-6));
    // Tilted by 70 degrees: not
    const double c7 = std::cos(70*M_PI/180), s7 = std::sin(70*M_PI/180);
    EXPECT_TRUE(SelfContactFilter::behindUnfaced(underside, V(s7, c7, 0), -1e-6));
    // Zero gap is touching, never behind
    EXPECT_FALSE(SelfContactFilter::behindUnfaced(underside, end, 0));
}


TEST(SelfContactFilter, everyOpposedPairHasOneSlaveOutsideTheBand)
{
    // Random unit normals n and partners -n tilted by up to 3 degrees:
    // at least one of the two is the slave; exactly one where the pair
    // is far from the band
    std::mt19937 gen(4);
    std::normal_distribution<double> g(0, 1);
    const V e(V(1, 2, 3).normalized());
    int both = 0;
    for (int k = 0; k < 20000; ++k)
    {
        const V n(V(g(gen), g(gen), g(gen)).normalized());
        const V axis(n.cross(V(g(gen), g(gen), g(gen))).normalized());
        const double tilt = 3*M_PI/180*std::abs(g(gen))/3;
        const V m(-(Eigen::AngleAxisd(tilt, axis)*n));
        const bool a = SelfContactFilter::slaveOfPair(n, m);
        const bool b = SelfContactFilter::slaveOfPair(m, n);
        ASSERT_TRUE(a || b) << "n = " << n.transpose() << ", m = " << m.transpose();
        if (std::abs((n - m).dot(e)) > SelfContactFilter::pairBand)
        {
            ASSERT_NE(a, b) << "n = " << n.transpose();
        }
        both += a && b;
    }
    // The band is narrow: few pairs have two slaves
    EXPECT_LT(both, 20000/10);
}


TEST(SelfContactFilter, axisAlignedPairsAreOutsideTheBand)
{
    // The usual geometry's pairs (faces along the axes and the 2D
    // diagonals) have one slave each
    const V dirs[] =
    {
        V(1, 0, 0), V(0, 1, 0), V(0, 0, 1),
        V(1, 1, 0).normalized(), V(1, -1, 0).normalized(),
        V(1, 0, 1).normalized(), V(0, 1, 1).normalized()
    };
    for (const V& n : dirs)
    {
        EXPECT_NE
        (
            SelfContactFilter::slaveOfPair(n, -n),
            SelfContactFilter::slaveOfPair(-n, n)
        ) << n.transpose();
    }
}
