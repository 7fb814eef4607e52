// Unit tests of the segment-to-segment overlap kernel,
// src/kernels/transfer/polygonOverlap. Overlaps are checked against
// closed-form areas (offset and rotated squares, one-cell-thick strips),
// against each other (symmetry, additivity over a fan of the master), and
// for conservation: over a tiled master the overlaps of a slave face add
// up to its projected area and the weights carry the total force over.

#include "polygonOverlap.H"

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace c4f::transfer;
using V = Eigen::Vector3d;

namespace
{

const double pi = 3.14159265358979323846;

//- Axis-aligned rectangle [x0,x1] x [y0,y1] at height z, counter-clockwise
//  about +z
Polygon rect(double x0, double x1, double y0, double y1, double z = 0)
{
    return {V(x0, y0, z), V(x1, y0, z), V(x1, y1, z), V(x0, y1, z)};
}

Polygon reversed(Polygon p)
{
    std::reverse(p.begin(), p.end());
    return p;
}

//- x -> R x + t for every vertex
Polygon moved(const Polygon& p, const Eigen::Matrix3d& R, const V& t)
{
    Polygon q;
    for (const V& x : p)
    {
        q.push_back(R*x + t);
    }
    return q;
}

double intervalOverlap(double a0, double a1, double b0, double b1)
{
    return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

//- Face in the y = y0 plane spanning z in [0, dz] and x in [x0, x1], as
//  on the front/back-bounded contact patch of a one-cell-thick 2D mesh;
//  `outward` picks which of the two orientations
Polygon stripFace(double x0, double x1, double y0, double dz, bool outward)
{
    Polygon p{V(x0, y0, 0), V(x1, y0, 0), V(x1, y0, dz), V(x0, y0, dz)};
    return outward ? p : reversed(p);
}

//- Orthonormal in-plane basis (e1, e2) for a unit normal n
void planeBasis(const V& n, V& e1, V& e2)
{
    e1 = n.unitOrthogonal();
    e2 = n.cross(e1);
}

//- The overlaps of one slave face with every master face must tile the
//  slave's shadow on `plane`, and its weights must sum to one; the shadow
//  and the overlap sum are added to the running totals
void checkSlaveFace
(
    const Polygon& s,
    const std::vector<Polygon>& master,
    const Plane& plane,
    std::vector<double>& w,
    double& shadowTotal,
    double& overlapTotal
)
{
    std::vector<double> A;
    double sumA = 0;
    for (const Polygon& m : master)
    {
        A.push_back(overlapArea(s, m));
        sumA += A.back();
    }
    const double shadow = polygonArea(projectOntoPlane(s, plane));
    EXPECT_NEAR(sumA, shadow, 1e-12*shadow);
    shadowTotal += shadow;
    overlapTotal += sumA;

    w = conservativeWeights(A);
    double sw = 0;
    for (const double x : w)
    {
        sw += x;
    }
    EXPECT_NEAR(sw, 1.0, 1e-15);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Plane and area  * * * * * * * * * * * * * //

TEST(PolygonOverlap, planeAndAreaFollowTheVertexOrder)
{
    const Polygon sq = rect(0, 2, 0, 3, 5);
    const Plane pl = polygonPlane(sq);
    EXPECT_NEAR((pl.origin - V(1, 1.5, 5)).norm(), 0, 1e-15);
    EXPECT_NEAR((pl.normal - V(0, 0, 1)).norm(), 0, 1e-15);
    EXPECT_NEAR(polygonArea(sq), 6.0, 1e-14);
    EXPECT_NEAR((polygonPlane(reversed(sq)).normal - V(0, 0, -1)).norm(), 0, 1e-15);
    EXPECT_NEAR(polygonArea(reversed(sq)), 6.0, 1e-14);

    // A warped quad (two corners up, two down by h): the Newell normal is
    // the mean one, +z by symmetry, and the area vector is the projected
    // area
    const double h = 0.01;
    const Polygon warped{V(0, 0, h), V(1, 0, -h), V(1, 1, h), V(0, 1, -h)};
    EXPECT_NEAR((polygonPlane(warped).normal - V(0, 0, 1)).norm(), 0, 1e-15);
    EXPECT_NEAR(polygonArea(warped), 1.0, 1e-15);
    EXPECT_NEAR(polygonPlane(warped).origin.z(), 0, 1e-15);

    // Degenerate inputs give zero, not NaN
    EXPECT_EQ(polygonArea(Polygon{V(0, 0, 0), V(1, 0, 0)}), 0.0);
    EXPECT_EQ(polygonPlane(Polygon{V(0, 0, 0), V(1, 1, 1), V(2, 2, 2)}).normal.norm(), 0.0);
}

TEST(PolygonOverlap, projectionOntoATiltedPlane)
{
    const Plane pl{V(1, 2, 3), V(1, 1, 1).normalized()};
    const Polygon p{V(0, 0, 0), V(4, -1, 2), V(-2, 5, 7)};
    const Polygon q = projectOntoPlane(p, pl);
    ASSERT_EQ(q.size(), p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        EXPECT_NEAR((q[i] - pl.origin).dot(pl.normal), 0, 1e-14);
        EXPECT_NEAR((p[i] - q[i]).cross(pl.normal).norm(), 0, 1e-14);
    }
}


// * * * * * * * * * * * * * * * * Clipping  * * * * * * * * * * * * * * * //

TEST(PolygonClip, triangleCutBySquare)
{
    // x + y <= 2 holds on all of the unit square, so clipping the
    // triangle (0,0)-(2,0)-(0,2) by it leaves the whole square
    const Polygon sq = rect(0, 1, 0, 1);
    const Polygon full = clipConvex({V(0, 0, 0), V(2, 0, 0), V(0, 2, 0)}, sq, V(0, 0, 1));
    EXPECT_NEAR(polygonArea(full), 1.0, 1e-15);

    // Triangle with legs on x = 0.5 (y in [-1, 0.5]) and y = 0.5 (x in
    // [0.5, 1.5]); its hypotenuse x = 0.5 + (y + 1)/1.5 crosses x = 1 at
    // y = -0.25, below the square, so inside the square it is the
    // rectangle [0.5, 1] x [0, 0.5]
    const Polygon tri{V(0.5, -1, 0), V(1.5, 0.5, 0), V(0.5, 0.5, 0)};
    for (const V& n : {V(0, 0, 1), V(0, 0, -3)})
    {
        for (const Polygon& clip : {sq, reversed(sq)})
        {
            const Polygon c = clipConvex(tri, clip, n);
            EXPECT_NEAR(polygonArea(c), 0.25, 1e-15);
            for (const V& x : c)
            {
                EXPECT_GE(x.x(), 0.5 - 1e-15);
                EXPECT_LE(x.x(), 1.0 + 1e-15);
                EXPECT_GE(x.y(), -1e-15);
                EXPECT_LE(x.y(), 0.5 + 1e-15);
            }
            // The subject's orientation survives
            EXPECT_GT(areaVector(c).dot(areaVector(tri)), 0);
        }
    }
}

TEST(PolygonClip, degenerateInputsGiveEmpty)
{
    const Polygon sq = rect(0, 1, 0, 1);
    EXPECT_TRUE(clipConvex(sq, {V(0, 0, 0), V(1, 0, 0)}, V(0, 0, 1)).empty());
    EXPECT_TRUE(clipConvex(sq, sq, V(0, 0, 0)).empty());
    // Clip polygon seen edge-on from the given normal
    EXPECT_TRUE(clipConvex(sq, sq, V(1, 0, 0)).empty());
    // Disjoint
    EXPECT_TRUE(clipConvex(rect(2, 3, 0, 1), sq, V(0, 0, 1)).empty());
}


// * * * * * * * * * * * * * * Closed-form overlaps * * * * * * * * * * * * //

TEST(PolygonOverlap, offsetUnitSquares)
{
    const Polygon master = rect(0, 1, 0, 1);
    const double d[] = {-0.9, -0.5, -0.25, 0, 0.1, 0.25, 1.0/3.0, 0.5, 0.9, 0.999};
    int n = 0;
    for (const double dx : d)
    {
        for (const double dy : d)
        {
            const Polygon slave = rect(dx, 1 + dx, dy, 1 + dy);
            const double expected = (1 - std::abs(dx))*(1 - std::abs(dy));
            EXPECT_NEAR(overlapArea(slave, master), expected, 1e-14) << dx << " " << dy;
            // Facing each other, the common case in contact
            EXPECT_NEAR(overlapArea(reversed(slave), master), expected, 1e-14);
            EXPECT_NEAR(overlapArea(slave, reversed(master)), expected, 1e-14);
            EXPECT_NEAR(overlapArea(reversed(slave), reversed(master)), expected, 1e-14);
            ++n;
        }
    }
    EXPECT_EQ(n, 100);
}

TEST(PolygonOverlap, liftedAndTiltedSlave)
{
    // Slave square offset by (dx, dy), lifted by h and tilted by theta
    // about its own x-parallel centre line: its shadow keeps the x-extent
    // and shrinks in y to cos(theta)
    const Polygon master = rect(0, 1, 0, 1);
    for (const double h : {0.0, 1e-9, 0.3, -0.2})
    {
        for (const double theta : {0.0, 0.01, 0.2, -0.35})
        {
            for (const V& d : {V(0.2, 0.3, 0), V(-0.4, 0.1, 0), V(0.05, -0.6, 0)})
            {
                const V c(0.5 + d.x(), 0.5 + d.y(), h);
                const Eigen::Matrix3d R =
                    Eigen::AngleAxisd(theta, V::UnitX()).toRotationMatrix();
                const Polygon slave =
                    moved(rect(-0.5, 0.5, -0.5, 0.5), R, c);
                const double hy = 0.5*std::cos(theta);
                const double expected =
                    intervalOverlap(c.x() - 0.5, c.x() + 0.5, 0, 1)
                   *intervalOverlap(c.y() - hy, c.y() + hy, 0, 1);
                EXPECT_NEAR(overlapArea(slave, master), expected, 1e-14)
                    << h << " " << theta;
                EXPECT_NEAR(overlapArea(reversed(slave), master), expected, 1e-14);
            }
        }
    }
}

TEST(PolygonOverlap, invariantUnderRigidMotionOfBothFaces)
{
    // The whole pair moved to an arbitrary plane far from the origin
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(0.7, V(1, -2, 0.5).normalized()).toRotationMatrix();
    const V t(1e3, -250, 37);
    const Polygon master = moved(rect(0, 1, 0, 1), R, t);
    const Polygon slave = moved(rect(0.3, 1.3, -0.2, 0.8, 0.01), R, t);
    EXPECT_NEAR(overlapArea(slave, master), 0.7*0.8, 1e-12);
    EXPECT_NEAR(overlapArea(reversed(slave), master), 0.7*0.8, 1e-12);
}

TEST(PolygonOverlap, toleranceScalesWithTheFaces)
{
    // Micro- and kilometre-sized faces: same relative answers, touching
    // faces still exactly zero, so the tolerance is not absolute
    for (const double L : {1e-6, 1.0, 1e4})
    {
        const Eigen::Matrix3d S = L*Eigen::Matrix3d::Identity();
        const V t = L*V(0.3, 0.2, 0.1);
        const Polygon master = moved(rect(0, 1, 0, 1), S, t);
        EXPECT_NEAR(overlapArea(moved(rect(0.2, 1.2, 0.5, 1.5, 1e-3), S, t), master),
                    0.8*0.5*L*L, 1e-14*L*L) << L;
        EXPECT_NEAR(overlapArea(moved(rect(0.5, 0.5 + 1e-9, 0, 1), S, t), master),
                    1e-9*L*L, 1e-14*L*L) << L;
        EXPECT_TRUE(overlapPolygon(moved(rect(1, 2, 0, 1), S, t), master).empty()) << L;
    }
}

TEST(PolygonOverlap, quadAgainstTriangle)
{
    // Unit square cut by x + y <= 1.5: loses a corner triangle of legs 0.5
    const Polygon sq = rect(0, 1, 0, 1);
    const Polygon tri{V(0, 0, 0.05), V(1.5, 0, 0.05), V(0, 1.5, 0.05)};
    const double expected = 1.0 - 0.5*0.5*0.5;
    EXPECT_NEAR(overlapArea(tri, sq), expected, 1e-15);
    EXPECT_NEAR(overlapArea(sq, tri), expected, 1e-15);
    EXPECT_NEAR(overlapArea(reversed(tri), sq), expected, 1e-15);
    EXPECT_NEAR(overlapArea(sq, reversed(tri)), expected, 1e-15);
    // A triangle stored as a quad with a repeated vertex clips the same
    const Polygon triAsQuad{tri[0], tri[1], tri[1], tri[2]};
    EXPECT_NEAR(overlapArea(sq, triAsQuad), expected, 1e-15);
}

TEST(PolygonOverlap, squareRotated45DegreesGivesARegularOctagon)
{
    // Both squares have inradius 1/2, so the intersection is the regular
    // octagon of inradius r = 1/2: area 8 r^2 tan(pi/8) = 2 (sqrt 2 - 1)
    const Polygon master = rect(-0.5, 0.5, -0.5, 0.5);
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(pi/4, V::UnitZ()).toRotationMatrix();
    const Polygon slave = moved(master, R, V(0, 0, 0.02));
    const double octagon = 2.0*(std::sqrt(2.0) - 1.0);
    EXPECT_NEAR(overlapArea(slave, master), octagon, 1e-15);
    EXPECT_NEAR(overlapArea(master, slave), octagon, 1e-15);
    EXPECT_NEAR(overlapArea(reversed(slave), master), octagon, 1e-15);
    EXPECT_EQ(overlapPolygon(slave, master).size(), 8u);
}

TEST(PolygonOverlap, containedDisjointAndIdentical)
{
    const Polygon big = rect(0, 1, 0, 1);
    const Polygon small = rect(0.2, 0.5, 0.3, 0.6, 0.1);
    EXPECT_NEAR(overlapArea(small, big), 0.09, 1e-15);
    EXPECT_NEAR(overlapArea(big, small), 0.09, 1e-15);
    EXPECT_NEAR(overlapArea(reversed(big), small), 0.09, 1e-15);

    EXPECT_EQ(overlapArea(rect(1.5, 2.5, 0, 1), big), 0.0);
    EXPECT_EQ(overlapArea(rect(-3, -2, -3, -2, 1), big), 0.0);
    EXPECT_TRUE(overlapPolygon(rect(1.5, 2.5, 0, 1), big).empty());

    EXPECT_NEAR(overlapArea(big, big), 1.0, 1e-15);
    EXPECT_NEAR(overlapArea(reversed(big), big), 1.0, 1e-15);
    // Identical faces in a general position: round-off puts each vertex a
    // few ulps inside or outside the other's edges, which must neither
    // add vertices nor lose area
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(0.9, V(-1, 0.2, 0.6).normalized()).toRotationMatrix();
    const Polygon bigMoved = moved(big, R, V(3.3, -0.7, 12.1));
    EXPECT_NEAR(overlapArea(reversed(bigMoved), bigMoved), 1.0, 1e-14);
    EXPECT_EQ(overlapPolygon(reversed(bigMoved), bigMoved).size(), 4u);
    EXPECT_EQ(overlapPolygon(bigMoved, bigMoved).size(), 4u);
    const Polygon tri{V(0, 0, 0), V(2, 0.1, 0), V(0.3, 1.7, 0)};
    EXPECT_NEAR(overlapArea(tri, tri), polygonArea(tri), 1e-15);
    EXPECT_NEAR(overlapArea(reversed(tri), tri), polygonArea(tri), 1e-15);
}

TEST(PolygonOverlap, touchingFacesGiveZero)
{
    const Polygon master = rect(0, 1, 0, 1);
    const Polygon touching[] = {
        rect(1, 2, 0, 1),       // shared edge
        rect(1, 2, 0.3, 1.3),   // part of an edge
        rect(1, 2, 1, 2),       // corner only
        rect(-1, 0, -0.5, 0.5, 0.2),
        rect(0, 1, 1, 2, -0.1)
    };
    for (const Polygon& s : touching)
    {
        for (const Polygon& slave : {s, reversed(s)})
        {
            const double a = overlapArea(slave, master);
            EXPECT_FALSE(std::isnan(a));
            EXPECT_EQ(a, 0.0);
            // Not a degenerate sliver but nothing at all
            EXPECT_TRUE(overlapPolygon(slave, master).empty());
        }
    }

    // The same contacts after a rigid motion of both faces: round-off now
    // puts the shared edge a few ulps either side
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(1.1, V(0.3, 0.4, -1).normalized()).toRotationMatrix();
    const V t(0.37, 11.3, -2.9);
    for (const Polygon& s : touching)
    {
        const Polygon sm = moved(reversed(s), R, t), mm = moved(master, R, t);
        const double a = overlapArea(sm, mm);
        EXPECT_FALSE(std::isnan(a));
        EXPECT_EQ(a, 0.0);
        EXPECT_TRUE(overlapPolygon(sm, mm).empty());
    }

    // Touching slave tilted a little: its shadow still ends on the edge
    const Eigen::Matrix3d Rt =
        Eigen::AngleAxisd(0.05, V::UnitY()).toRotationMatrix();
    const Polygon tilted = moved(rect(0, 1, 0, 1), Rt, V(1, 0, 0.01));
    EXPECT_NEAR(overlapArea(tilted, master), 0.0, 1e-15);
}

TEST(PolygonOverlap, edgeOnSlaveAndDegenerateMasterGiveZero)
{
    const Polygon master = rect(0, 1, 0, 1);
    // Vertical slave standing on the master: its shadow is a segment
    const Polygon edgeOn{V(0.2, 0.5, 0), V(0.8, 0.5, 0), V(0.8, 0.5, 1), V(0.2, 0.5, 1)};
    EXPECT_EQ(overlapArea(edgeOn, master), 0.0);
    // ... also where round-off leaves its shadow a few ulps wide
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(0.4, V(2, 1, -1).normalized()).toRotationMatrix();
    const V t(-5.5, 0.1, 7.7);
    EXPECT_EQ(overlapArea(moved(edgeOn, R, t), moved(master, R, t)), 0.0);
    EXPECT_TRUE(overlapPolygon(moved(edgeOn, R, t), moved(master, R, t)).empty());
    // Collapsed master (all vertices on a line)
    const Polygon line{V(0, 0, 0), V(0.5, 0.5, 0), V(1, 1, 0)};
    EXPECT_EQ(overlapArea(master, line), 0.0);
    EXPECT_EQ(overlapArea(master, Polygon{}), 0.0);
    EXPECT_EQ(overlapArea(Polygon{V(0, 0, 0)}, master), 0.0);
}

TEST(PolygonOverlap, nearlyCoplanarWarpedFaces)
{
    // Vertices off the plane by round-off-to-tolerance amounts do not
    // change the overlap beyond the same order
    const double eps = 1e-10;
    const Polygon master{V(0, 0, eps), V(1, 0, -eps), V(1, 1, eps), V(0, 1, -eps)};
    const Polygon slave{V(0.5, 0.25, -eps), V(0.5, 1.25, 2*eps), V(1.5, 1.25, 0), V(1.5, 0.25, eps)};
    EXPECT_NEAR(overlapArea(slave, master), 0.5*0.75, 1e-13);
}


// * * * * * * * * * * * * * One-cell-thick (2D) cases * * * * * * * * * * * //

TEST(PolygonOverlap, oneCellThickStrips)
{
    const double dz = 0.1;
    const double x[][4] = {
        // master [x0,x1], slave [s0,s1]
        {0, 1, 0.25, 0.75},
        {0, 1, 0.5, 1.5},
        {0, 1, -2, 0.3},
        {0.2, 0.45, 0.1, 0.9},
        {0, 1, 1, 2},
        {0, 1, 1.2, 2},
        {0.3, 0.31, 0.305, 0.4}
    };
    for (const auto& c : x)
    {
        // Master faces +y, slave at a small gap facing -y
        const Polygon master = stripFace(c[0], c[1], 0, dz, true);
        const Polygon slave = stripFace(c[2], c[3], 1e-3, dz, false);
        const double expected = dz*intervalOverlap(c[0], c[1], c[2], c[3]);
        EXPECT_NEAR(overlapArea(slave, master), expected, 1e-15)
            << c[0] << " " << c[1] << " " << c[2] << " " << c[3];
        EXPECT_NEAR(overlapArea(master, slave), expected, 1e-15);
    }
}

TEST(PolygonOverlap, oneCellThickInclinedSlave)
{
    // Slave facet on a slightly inclined plane (a cylinder's facet) over a
    // flat master: the shadow is the facet's x-projection times dz
    const double dz = 0.1;
    const Polygon master = stripFace(0, 1, 0, dz, true);
    for (const double phi : {0.01, 0.05, 0.2, -0.1})
    {
        for (const double s0 : {-0.3, 0.0, 0.4, 0.9})
        {
            const double L = 0.5;
            const V a(s0, 0.02, 0), b(s0 + L*std::cos(phi), 0.02 + L*std::sin(phi), 0);
            // Facing the master (-y-ish): a, a+dz, b+dz, b
            const Polygon slave{a, a + V(0, 0, dz), b + V(0, 0, dz), b};
            const double expected =
                dz*intervalOverlap(0, 1, std::min(a.x(), b.x()), std::max(a.x(), b.x()));
            EXPECT_NEAR(overlapArea(slave, master), expected, 1e-15)
                << phi << " " << s0;
        }
    }
}


// * * * * * * * * * * * * * * * Conservation  * * * * * * * * * * * * * * //

TEST(ConservativeTransfer, weightsAreAPartitionOfUnity)
{
    EXPECT_TRUE(conservativeWeights({}).empty());
    EXPECT_TRUE(conservativeWeights({0.0, 0.0, 0.0}).empty());

    const std::vector<double> one = conservativeWeights({0.0, 3e-7, 0.0});
    ASSERT_EQ(one.size(), 3u);
    EXPECT_EQ(one[0], 0.0);
    EXPECT_EQ(one[1], 1.0);
    EXPECT_EQ(one[2], 0.0);

    const std::vector<double> A{0.1, 0.2, 0.3, 1.0/3.0, 1e-9, 0.0, 0.7};
    const std::vector<double> w = conservativeWeights(A);
    ASSERT_EQ(w.size(), A.size());
    double sum = 0, sumA = 0;
    for (std::size_t j = 0; j < A.size(); ++j)
    {
        sum += w[j];
        sumA += A[j];
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
    for (std::size_t j = 0; j < A.size(); ++j)
    {
        EXPECT_NEAR(w[j], A[j]/sumA, 1e-15);
        EXPECT_GE(w[j], 0.0);
    }

    // Many candidates of disparate size: the independently rounded
    // quotients alone can miss 1 by several ulps; with the residual put
    // on the largest weight the sum is within one ulp
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(0, 1);
    double worst = 0;
    for (int trial = 0; trial < 2000; ++trial)
    {
        std::vector<double> B(2 + trial % 40);
        for (double& b : B)
        {
            b = std::pow(10.0, -3*u(gen));
        }
        const std::vector<double> wb = conservativeWeights(B);
        ASSERT_EQ(wb.size(), B.size());
        double s = 0;
        for (const double x : wb)
        {
            s += x;
        }
        worst = std::max(worst, std::abs(s - 1.0));
    }
    EXPECT_LE(worst, std::numeric_limits<double>::epsilon());
}

TEST(ConservativeTransfer, tiledStripCarriesTheTotalForce)
{
    // One-cell-thick contact strip x in [0,1]: 7 uneven master faces, 10
    // uneven slave faces facing them, and the slave strip slightly tilted
    const double dz = 0.1;
    const std::vector<double> xm{0, 0.11, 0.3, 0.42, 0.55, 0.71, 0.86, 1.0};
    std::vector<double> xs(11);
    for (int i = 0; i <= 10; ++i)
    {
        xs[i] = 0.1*i + (i > 0 && i < 10 ? 0.03*std::sin(3.0*i) : 0.0);
    }

    std::vector<Polygon> master, slave;
    for (std::size_t j = 0; j + 1 < xm.size(); ++j)
    {
        master.push_back(stripFace(xm[j], xm[j + 1], 0, dz, true));
    }
    for (std::size_t i = 0; i + 1 < xs.size(); ++i)
    {
        const double y0 = 1e-3 + 0.01*xs[i], y1 = 1e-3 + 0.01*xs[i + 1];
        slave.push_back
        (
            {V(xs[i], y0, dz), V(xs[i], y0, 0), V(xs[i + 1], y1, 0), V(xs[i + 1], y1, dz)}
        );
    }

    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(-1, 1);
    V fSlave = V::Zero();
    std::vector<V> fMaster(master.size(), V::Zero());
    double slaveShadow = 0, overlapTotal = 0;

    for (const Polygon& s : slave)
    {
        std::vector<double> w;
        checkSlaveFace
        (
            s, master, polygonPlane(master[0]), w, slaveShadow, overlapTotal
        );
        ASSERT_EQ(w.size(), master.size());

        for (const V& f : {V(0, 1, 0), V(u(gen), u(gen), u(gen))})
        {
            fSlave += f;
            for (std::size_t j = 0; j < master.size(); ++j)
            {
                fMaster[j] += w[j]*f;
            }
        }
    }

    V fM = V::Zero();
    for (const V& f : fMaster)
    {
        fM += f;
    }
    EXPECT_NEAR((fM - fSlave).norm(), 0, 1e-13*fSlave.norm());
    EXPECT_NEAR(overlapTotal, dz*1.0, 1e-13);
    EXPECT_NEAR(slaveShadow, dz*1.0, 1e-13);
}

TEST(ConservativeTransfer, randomTilingOfATiltedPlane)
{
    // Master: a jittered grid of triangles on an arbitrary plane; slave: a
    // different jittered grid of warped quads floating just above it,
    // facing it, and lying within the master's extent
    std::mt19937 gen(2024);
    std::uniform_real_distribution<double> u(-1, 1);

    const V n = V(0.3, -0.5, 0.8).normalized();
    const V o(2.0, -1.0, 0.5);
    V e1, e2;
    planeBasis(n, e1, e2);
    const auto onPlane = [&](double a, double b, double h)
    {
        return V(o + a*e1 + b*e2 + h*n);
    };

    // Master grid 12 x 12 on [0,1.2]^2, triangles (always convex)
    const int Nm = 12;
    const double hm = 0.1;
    std::vector<std::vector<V>> pm(Nm + 1, std::vector<V>(Nm + 1));
    for (int i = 0; i <= Nm; ++i)
    {
        for (int j = 0; j <= Nm; ++j)
        {
            const bool edge = i == 0 || j == 0 || i == Nm || j == Nm;
            const double ja = edge ? 0 : 0.3*hm*u(gen);
            const double jb = edge ? 0 : 0.3*hm*u(gen);
            pm[i][j] = onPlane(i*hm + ja, j*hm + jb, 0);
        }
    }
    std::vector<Polygon> master;
    for (int i = 0; i < Nm; ++i)
    {
        for (int j = 0; j < Nm; ++j)
        {
            // Alternate the diagonal and the orientation
            if ((i + j) % 2)
            {
                master.push_back({pm[i][j], pm[i + 1][j], pm[i + 1][j + 1]});
                master.push_back(reversed({pm[i][j], pm[i + 1][j + 1], pm[i][j + 1]}));
            }
            else
            {
                master.push_back({pm[i][j], pm[i + 1][j], pm[i][j + 1]});
                master.push_back({pm[i + 1][j], pm[i + 1][j + 1], pm[i][j + 1]});
            }
        }
    }

    // Slave grid 7 x 7 on [0.15,1.05]^2, quads warped by 1e-3 of their
    // size out of plane, lifted by a gap, facing -n
    const int Ns = 7;
    const double s0 = 0.15, hs = 0.9/Ns;
    std::vector<std::vector<V>> ps(Ns + 1, std::vector<V>(Ns + 1));
    for (int i = 0; i <= Ns; ++i)
    {
        for (int j = 0; j <= Ns; ++j)
        {
            ps[i][j] = onPlane
            (
                s0 + i*hs + 0.25*hs*u(gen),
                s0 + j*hs + 0.25*hs*u(gen),
                0.01 + 1e-3*hs*u(gen)
            );
        }
    }

    const Plane plane{o, n};
    V fSlave = V::Zero(), fMaster = V::Zero();
    double shadowTotal = 0, overlapTotal = 0;
    for (int i = 0; i < Ns; ++i)
    {
        for (int j = 0; j < Ns; ++j)
        {
            const Polygon s{ps[i][j], ps[i][j + 1], ps[i + 1][j + 1], ps[i + 1][j]};
            SCOPED_TRACE(testing::Message() << "slave face " << i << " " << j);
            std::vector<double> w;
            checkSlaveFace(s, master, plane, w, shadowTotal, overlapTotal);
            ASSERT_EQ(w.size(), master.size());

            const V f(u(gen), u(gen), 1 + u(gen));
            fSlave += f;
            for (std::size_t k = 0; k < master.size(); ++k)
            {
                fMaster += w[k]*f;
            }
        }
    }
    EXPECT_NEAR((fMaster - fSlave).norm(), 0, 1e-13*fSlave.norm());
    EXPECT_NEAR(overlapTotal, shadowTotal, 1e-12*shadowTotal);
    // The slave patch's boundary nodes are jittered too, so its size is
    // only about 0.9^2
    EXPECT_NEAR(shadowTotal, 0.81, 0.1);
}


// * * * * * * * * * * * * * * Randomized sweep  * * * * * * * * * * * * * //

TEST(PolygonOverlap, randomConvexPairsAreSymmetricBoundedAndAdditive)
{
    std::mt19937 gen(12345);
    std::uniform_real_distribution<double> u(0, 1);

    int nOverlapping = 0;
    for (int trial = 0; trial < 1000; ++trial)
    {
        // A random plane per pair
        const V n = V(u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5).normalized();
        const V o(10*u(gen), 10*u(gen), 10*u(gen));
        V e1, e2;
        planeBasis(n, e1, e2);

        // Convex polygons: vertices on an ellipse at sorted angles
        const auto randomConvex = [&]()
        {
            const int m = 3 + int(6*u(gen));
            std::vector<double> t(m);
            for (double& x : t)
            {
                x = 2*pi*u(gen);
            }
            std::sort(t.begin(), t.end());
            const double ra = 0.2 + u(gen), rb = 0.2 + u(gen);
            const double c1 = u(gen), c2 = u(gen), rot = 2*pi*u(gen);
            Polygon p;
            for (const double x : t)
            {
                const double a = ra*std::cos(x), b = rb*std::sin(x);
                const double ar = std::cos(rot)*a - std::sin(rot)*b;
                const double br = std::sin(rot)*a + std::cos(rot)*b;
                p.push_back(o + (c1 + ar)*e1 + (c2 + br)*e2);
            }
            return u(gen) < 0.5 ? p : reversed(p);
        };

        const Polygon A = randomConvex();
        const Polygon B = randomConvex();
        const double aA = polygonArea(A), aB = polygonArea(B);
        const double scale = std::max(aA, aB);

        const double ab = overlapArea(A, B);
        const double ba = overlapArea(B, A);
        ASSERT_FALSE(std::isnan(ab));
        EXPECT_NEAR(ab, ba, 1e-12*scale) << trial;
        EXPECT_GE(ab, 0.0);
        EXPECT_LE(ab, std::min(aA, aB)*(1 + 1e-12) + 1e-15);
        if (ab > 0)
        {
            ++nOverlapping;
        }

        // Additive over a fan split of the master about its first vertex
        double fan = 0;
        for (std::size_t k = 1; k + 1 < B.size(); ++k)
        {
            fan += overlapArea(A, Polygon{B[0], B[k], B[k + 1]});
        }
        EXPECT_NEAR(fan, ab, 1e-12*scale) << trial;

        // And the overlap with itself is the whole polygon
        EXPECT_NEAR(overlapArea(A, A), aA, 1e-13*aA);
    }
    // The sweep actually exercised partial overlaps
    EXPECT_GT(nOverlapping, 300);
}

TEST(polygonCentroid, rectangleTriangleAndLShape)
{
    // A rectangle anywhere in space: its centre
    const V o(3.1, -2.0, 7.5), e1(0.4, 0.1, 0), e2(-0.02, 0.08, 0.3);
    const Polygon box{o, o + e1, o + e1 + e2, o + e2};
    EXPECT_NEAR((polygonCentroid(box) - (o + 0.5*(e1 + e2))).norm(), 0, 1e-14);

    // A triangle: the mean of its vertices, either orientation
    const Polygon tri{V(0, 0, 0), V(3, 0, 0), V(0, 6, 0)};
    EXPECT_NEAR((polygonCentroid(tri) - V(1, 2, 0)).norm(), 0, 1e-14);
    const Polygon triRev{tri[2], tri[1], tri[0]};
    EXPECT_NEAR((polygonCentroid(triRev) - V(1, 2, 0)).norm(), 0, 1e-14);

    // A concave L of three unit squares, (1/3)(c1 + c2 + c3): not the
    // vertex average
    const Polygon L{V(0, 0, 0), V(2, 0, 0), V(2, 1, 0), V(1, 1, 0), V(1, 2, 0), V(0, 2, 0)};
    const V expected = (V(0.5, 0.5, 0) + V(1.5, 0.5, 0) + V(0.5, 1.5, 0))/3.0;
    EXPECT_NEAR((polygonCentroid(L) - expected).norm(), 0, 1e-14);

    // Degenerate (a segment) and empty: no NaN
    const Polygon seg{V(0, 0, 0), V(1, 0, 0), V(2, 0, 0)};
    EXPECT_TRUE(polygonCentroid(seg).allFinite());
    EXPECT_NEAR((polygonCentroid(seg) - V(1, 0, 0)).norm(), 0, 1e-15);
    EXPECT_TRUE(polygonCentroid(Polygon()).allFinite());
}

TEST(polygonCentroid, firstMomentOfAnOverlapSplitsAdditively)
{
    // The centroid of a slave face's projection is the area-weighted mean
    // of the centroids of its overlaps with master faces that tile it
    const Polygon slave{V(0.1, 0.0, 0.02), V(0.9, 0.0, 0.03), V(0.9, 1.0, 0.01), V(0.1, 1.0, 0.0)};
    const Polygon m1{V(0, 0, 0), V(0.45, 0, 0), V(0.45, 1, 0), V(0, 1, 0)};
    const Polygon m2{V(0.45, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0.45, 1, 0)};
    const Polygon o1 = overlapPolygon(slave, m1), o2 = overlapPolygon(slave, m2);
    const double a1 = polygonArea(o1), a2 = polygonArea(o2);
    const V mean = (a1*polygonCentroid(o1) + a2*polygonCentroid(o2))/(a1 + a2);
    EXPECT_NEAR(mean.x(), 0.5, 1e-14);
    EXPECT_NEAR(mean.y(), 0.5, 1e-14);
    EXPECT_NEAR(polygonCentroid(o1).x(), 0.275, 1e-14);
}


TEST(ProjectsInside, aboveBelowBesideAndOnTheEdge)
{
    const Polygon sq = rect(0, 1, 0, 1);
    // Height above or below the plane does not matter, nor the numbering
    for (const Polygon& p : {sq, reversed(sq)})
    {
        EXPECT_TRUE(projectsInside(V(0.5, 0.5, 0), p));
        EXPECT_TRUE(projectsInside(V(0.2, 0.9, 3.0), p));
        EXPECT_TRUE(projectsInside(V(0.2, 0.9, -7.0), p));
        EXPECT_TRUE(projectsInside(V(1.0, 0.5, -1.0), p));
        EXPECT_TRUE(projectsInside(V(0.0, 0.0, 1.0), p));
        EXPECT_FALSE(projectsInside(V(1.0 + 1e-6, 0.5, -1.0), p));
        EXPECT_FALSE(projectsInside(V(-0.5, 0.5, 0), p));
        EXPECT_FALSE(projectsInside(V(0.5, 2.0, 0.1), p));
    }
}


TEST(ProjectsInside, tiltedTriangleAndDegenerateInput)
{
    // A triangle in the plane x + y + z = 1; points moved along its normal
    // keep their answer
    const Polygon tri{V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)};
    const V n = V(1, 1, 1).normalized();
    const V c = (tri[0] + tri[1] + tri[2])/3.0;
    for (const double h : {-2.0, 0.0, 0.3, 5.0})
    {
        EXPECT_TRUE(projectsInside(c + h*n, tri));
        EXPECT_FALSE(projectsInside(V(1, 1, -1) + h*n, tri));
    }
    EXPECT_FALSE(projectsInside(c, Polygon{V(0, 0, 0), V(1, 0, 0)}));
    EXPECT_FALSE
    (
        projectsInside(V(0.5, 0, 0), Polygon{V(0, 0, 0), V(1, 0, 0), V(2, 0, 0)})
    );
}
