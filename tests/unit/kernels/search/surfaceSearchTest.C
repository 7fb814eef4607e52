// Unit tests of the proximity search, src/kernels/search/surfaceSearch.
// The CGAL tree is checked against the brute-force loop over all triangles
// on curved surfaces of non-planar quads, and both against geometry whose
// answer is known in closed form (flat grids, heights above face centres).
// Where the closest point lies on an edge shared by two faces either face
// is right; the comparisons then check that the other face is exactly as
// close instead of requiring the same index.

#include "surfaceSearch.H"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

using namespace c4f::search;
using V = Eigen::Vector3d;
using Faces = std::vector<std::vector<int>>;

namespace
{

const double inf = std::numeric_limits<double>::infinity();

struct Surface
{
    std::vector<V> points;
    Faces faces;
};

//- nx by ny quads over [0, lx] x [0, ly], heights z(x, y); quad (i, j) is
//  face i + nx*j, counter-clockwise seen from +z
template<class ZFunction>
Surface grid(int nx, int ny, double lx, double ly, ZFunction z)
{
    Surface s;
    for (int j = 0; j <= ny; ++j)
    {
        for (int i = 0; i <= nx; ++i)
        {
            const double x = lx*i/nx, y = ly*j/ny;
            s.points.emplace_back(x, y, z(x, y));
        }
    }
    const auto id = [nx](int i, int j) { return i + (nx + 1)*j; };
    for (int j = 0; j < ny; ++j)
    {
        for (int i = 0; i < nx; ++i)
        {
            s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    }
    return s;
}

Surface flatGrid(int nx, int ny)
{
    return grid(nx, ny, nx, ny, [](double, double) { return 0.0; });
}

//- The height field z = 0.1 sin(3x) cos(2y) on a 20x20 grid of [0, 1]^2,
//  with jittered heights so that no two quads are alike and all are
//  non-planar; every seventh quad is split into two triangles so that
//  triangle faces are searched too
Surface wavySurface(std::mt19937& rng)
{
    std::uniform_real_distribution<double> jitter(-0.01, 0.01);
    Surface s = grid
    (
        20, 20, 1.0, 1.0,
        [&](double x, double y) { return 0.1*std::sin(3*x)*std::cos(2*y) + jitter(rng); }
    );
    Faces faces;
    for (std::size_t f = 0; f < s.faces.size(); ++f)
    {
        const std::vector<int>& q = s.faces[f];
        if (f % 7 == 3)
        {
            faces.push_back({q[0], q[1], q[2]});
            faces.push_back({q[0], q[2], q[3]});
        }
        else
        {
            faces.push_back(q);
        }
    }
    s.faces = faces;
    return s;
}

//- Open cylinder of radius 1 along z in [0, 2], 24 x 8 quads; ring k is
//  turned by 0.2 k rad so that the quads are twisted (non-planar)
Surface twistedCylinder()
{
    const int nt = 24, nz = 8;
    const double pi = std::acos(-1.0);
    Surface s;
    for (int k = 0; k <= nz; ++k)
    {
        for (int i = 0; i < nt; ++i)
        {
            const double t = 2*pi*i/nt + 0.2*k;
            s.points.emplace_back(std::cos(t), std::sin(t), 2.0*k/nz);
        }
    }
    for (int k = 0; k < nz; ++k)
    {
        for (int i = 0; i < nt; ++i)
        {
            const int i1 = (i + 1) % nt;
            s.faces.push_back({i + nt*k, i1 + nt*k, i1 + nt*(k + 1), i + nt*(k + 1)});
        }
    }
    return s;
}

std::vector<V> randomPoints(std::mt19937& rng, const V& lo, const V& hi, int n)
{
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<V> q;
    for (int i = 0; i < n; ++i)
    {
        q.emplace_back
        (
            lo.x() + (hi.x() - lo.x())*u(rng),
            lo.y() + (hi.y() - lo.y())*u(rng),
            lo.z() + (hi.z() - lo.z())*u(rng)
        );
    }
    return q;
}

//- Distance from q to one face alone
double distanceToFace(const Surface& s, int face, const V& q)
{
    return bruteForceClosest(s.points, {s.faces.at(face)}, q, inf).distance;
}

//- hit is the closest point on s to q: same distance and point as the
//  reference, and the reported face really carries that point. Returns
//  whether the face index equals the reference's
bool expectSameHit(const Surface& s, const V& q, const SearchHit& hit, const SearchHit& ref)
{
    EXPECT_TRUE(hit.found);
    EXPECT_TRUE(ref.found);
    EXPECT_NEAR(hit.distance, ref.distance, 1e-12);
    EXPECT_NEAR(hit.distance, (q - hit.point).norm(), 1e-15);
    // The face index maps back to a face that contains the point
    EXPECT_NEAR(distanceToFace(s, hit.face, hit.point), 0, 1e-12);
    // The closest point is unique (no query sits on a medial axis), even
    // where the face is not
    EXPECT_NEAR((hit.point - ref.point).norm(), 0, 1e-12);
    if (hit.face == ref.face)
    {
        return true;
    }
    // Equidistant faces: the point is on an edge or vertex of both
    EXPECT_NEAR(distanceToFace(s, ref.face, hit.point), 0, 1e-12);
    return false;
}

void expectMatchesBruteForce(const Surface& s, const std::vector<V>& queries)
{
    SurfaceSearch search;
    search.build(s.points, s.faces);
    int sameFace = 0;
    for (const V& q : queries)
    {
        const SearchHit hit = search.closest(q, inf);
        const SearchHit ref = bruteForceClosest(s.points, s.faces, q, inf);
        sameFace += expectSameHit(s, q, hit, ref);
    }
    // Ties need the closest point on an edge or vertex shared by two
    // faces; on these surfaces that is 15-25 % of the queries, which the
    // two searches may resolve differently. The rest must name the same
    // face, or the triangle-to-face mapping is broken
    EXPECT_GT(sameFace, 0.5*queries.size());
}

//- Test-side reference for facesInBox: the fan of the header, and the
//  closed box-against-bounding-box test
std::vector<int> facesInBoxReference(const Surface& s, const V& lo, const V& hi)
{
    std::vector<int> out;
    for (std::size_t f = 0; f < s.faces.size(); ++f)
    {
        const std::vector<int>& face = s.faces[f];
        std::vector<std::vector<V>> tris;
        if (face.size() == 3)
        {
            tris.push_back({s.points[face[0]], s.points[face[1]], s.points[face[2]]});
        }
        else
        {
            V c = V::Zero();
            for (int v : face) c += s.points[v];
            c /= face.size();
            for (std::size_t i = 0; i < face.size(); ++i)
            {
                tris.push_back({s.points[face[i]], s.points[face[(i + 1) % face.size()]], c});
            }
        }
        for (const auto& t : tris)
        {
            const V tlo = t[0].cwiseMin(t[1]).cwiseMin(t[2]);
            const V thi = t[0].cwiseMax(t[1]).cwiseMax(t[2]);
            if ((tlo.array() <= hi.array()).all() && (lo.array() <= thi.array()).all())
            {
                out.push_back(int(f));
                break;
            }
        }
    }
    return out;
}

//- Runs f, expects std::invalid_argument whose message contains `text`
template<class F>
void expectInvalid(F f, const std::string& text)
{
    try
    {
        f();
        ADD_FAILURE() << "no exception; expected one mentioning \"" << text << "\"";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos)
            << "message: " << e.what();
    }
}

} // End anonymous namespace


TEST(surfaceSearch, countsFacesAndFanTriangles)
{
    std::mt19937 rng(1);
    const Surface s = wavySurface(rng);
    SurfaceSearch search;
    EXPECT_EQ(search.nFaces(), 0);
    EXPECT_EQ(search.nTriangles(), 0);
    search.build(s.points, s.faces);
    // 400 cells, 57 of them (f % 7 == 3) split into two triangle faces
    EXPECT_EQ(search.nFaces(), 343 + 2*57);
    EXPECT_EQ(search.nTriangles(), 4*343 + 2*57);
}

TEST(surfaceSearch, matchesBruteForceOnWavySurface)
{
    std::mt19937 rng(2);
    const Surface s = wavySurface(rng);
    expectMatchesBruteForce
    (
        s,
        randomPoints(rng, V(-0.3, -0.3, -0.4), V(1.3, 1.3, 0.4), 2000)
    );
}

TEST(surfaceSearch, matchesBruteForceOnTwistedCylinder)
{
    std::mt19937 rng(3);
    const Surface s = twistedCylinder();
    // Inside and outside, beyond both open ends
    expectMatchesBruteForce
    (
        s,
        randomPoints(rng, V(-1.5, -1.5, -0.5), V(1.5, 1.5, 2.5), 2000)
    );
}

TEST(surfaceSearch, bruteForceKnowsVertexEdgeAndInteriorRegions)
{
    // One triangle in z = 0; each query's answer is known by hand
    const std::vector<V> p = {V(0, 0, 0), V(2, 0, 0), V(0, 2, 0)};
    const Faces f = {{0, 1, 2}};
    const auto at = [&](const V& q) { return bruteForceClosest(p, f, q, inf).point; };
    EXPECT_NEAR((at(V(-1, -1, 1)) - V(0, 0, 0)).norm(), 0, 1e-15);       // vertex a
    EXPECT_NEAR((at(V(3, -1, 0.5)) - V(2, 0, 0)).norm(), 0, 1e-15);      // vertex b
    EXPECT_NEAR((at(V(-0.5, 3, 0)) - V(0, 2, 0)).norm(), 0, 1e-15);      // vertex c
    EXPECT_NEAR((at(V(1, -3, 2)) - V(1, 0, 0)).norm(), 0, 1e-15);        // edge ab
    EXPECT_NEAR((at(V(-4, 0.5, 0)) - V(0, 0.5, 0)).norm(), 0, 1e-15);    // edge ca
    EXPECT_NEAR((at(V(2, 2, -1)) - V(1, 1, 0)).norm(), 0, 1e-15);        // edge bc
    EXPECT_NEAR((at(V(0.5, 0.7, -3)) - V(0.5, 0.7, 0)).norm(), 0, 1e-15); // interior
    EXPECT_NEAR(bruteForceClosest(p, f, V(2, 2, -1), inf).distance, std::sqrt(3.0), 1e-15);
}

TEST(surfaceSearch, pointOnFaceHasZeroDistance)
{
    const Surface s = flatGrid(4, 3);
    SurfaceSearch search;
    search.build(s.points, s.faces);

    // Inside cell (2, 1), off every fan edge
    const V q(2.3, 1.6, 0);
    const SearchHit hit = search.closest(q, inf);
    ASSERT_TRUE(hit.found);
    EXPECT_EQ(hit.face, 2 + 4*1);
    EXPECT_NEAR(hit.distance, 0, 1e-15);
    EXPECT_NEAR((hit.point - q).norm(), 0, 1e-15);

    // On the edge x = 2 between cells (1, 2) and (2, 2): either face
    const SearchHit edge = search.closest(V(2, 2.4, 0), inf);
    ASSERT_TRUE(edge.found);
    EXPECT_TRUE(edge.face == 1 + 4*2 || edge.face == 2 + 4*2) << edge.face;
    EXPECT_NEAR(edge.distance, 0, 1e-15);
}

TEST(surfaceSearch, pointAboveFaceCentreHitsThatFaceAtItsHeight)
{
    const Surface s = flatGrid(4, 3);
    SurfaceSearch search;
    search.build(s.points, s.faces);
    for (int j = 0; j < 3; ++j)
    {
        for (int i = 0; i < 4; ++i)
        {
            for (const double h : {0.7, -0.25, 3.0})
            {
                const SearchHit hit = search.closest(V(i + 0.5, j + 0.5, h), inf);
                ASSERT_TRUE(hit.found);
                EXPECT_EQ(hit.face, i + 4*j);
                EXPECT_NEAR(hit.distance, std::abs(h), 1e-15);
                EXPECT_NEAR((hit.point - V(i + 0.5, j + 0.5, 0)).norm(), 0, 1e-15);
            }
        }
    }
}

TEST(surfaceSearch, pointAboveFaceCentreOfRotatedGrid)
{
    // The same flat grid turned off the axes: the answer must not depend
    // on the boxes being tight
    Surface s = flatGrid(5, 5);
    const Eigen::Matrix3d R =
        (Eigen::AngleAxisd(0.7, V(1, 2, 3).normalized())).toRotationMatrix();
    const V shift(0.3, -1.2, 2.0);
    for (V& p : s.points) p = R*p + shift;
    SurfaceSearch search;
    search.build(s.points, s.faces);

    const V n = R*V(0, 0, 1);
    const V centre = R*V(3.5, 1.5, 0) + shift;
    const SearchHit hit = search.closest(centre + 0.4*n, inf);
    ASSERT_TRUE(hit.found);
    EXPECT_EQ(hit.face, 3 + 5*1);
    EXPECT_NEAR(hit.distance, 0.4, 1e-14);
    EXPECT_NEAR((hit.point - centre).norm(), 0, 1e-14);
}

TEST(surfaceSearch, maxDistanceCutsOff)
{
    const Surface s = flatGrid(4, 3);
    SurfaceSearch search;
    search.build(s.points, s.faces);
    const V q(1.5, 2.5, 0.7);

    const SearchHit beyond = search.closest(q, 0.7*(1 - 1e-9));
    EXPECT_FALSE(beyond.found);
    EXPECT_EQ(beyond.face, -1);

    const SearchHit inside = search.closest(q, 0.7*(1 + 1e-9));
    ASSERT_TRUE(inside.found);
    EXPECT_EQ(inside.face, 1 + 4*2);
    EXPECT_NEAR(inside.distance, 0.7, 1e-15);

    // The reference cuts off the same way
    EXPECT_FALSE(bruteForceClosest(s.points, s.faces, q, 0.7*(1 - 1e-9)).found);
    EXPECT_TRUE(bruteForceClosest(s.points, s.faces, q, 0.7*(1 + 1e-9)).found);

    // On the surface, zero tolerance still finds it
    EXPECT_TRUE(search.closest(V(2.3, 1.6, 0), 0).found);
    // Far away with the limit, found without
    EXPECT_FALSE(search.closest(V(40, 0, 0), 10).found);
    EXPECT_NEAR(search.closest(V(40, 0, 0), inf).distance, 36, 1e-14);
}

TEST(surfaceSearch, translatedSurfaceGivesTranslatedHits)
{
    std::mt19937 rng(4);
    const Surface s = wavySurface(rng);
    SurfaceSearch search;
    search.build(s.points, s.faces);
    const std::vector<V> queries =
        randomPoints(rng, V(-0.3, -0.3, -0.4), V(1.3, 1.3, 0.4), 300);
    std::vector<SearchHit> before;
    for (const V& q : queries) before.push_back(search.closest(q, inf));

    const V t(0.3, -2.2, 0.7);
    Surface moved = s;
    for (V& p : moved.points) p += t;
    search.move(moved.points);
    EXPECT_EQ(search.nFaces(), int(s.faces.size()));

    int sameFace = 0;
    for (std::size_t i = 0; i < queries.size(); ++i)
    {
        SearchHit expected = before[i];
        expected.point += t;
        const V q = queries[i] + t;
        sameFace += expectSameHit(moved, q, search.closest(q, inf), expected);
    }
    EXPECT_GT(sameFace, 0.5*queries.size());

    // Nothing is left of the old position: its points are now far away
    const SearchHit old = search.closest(before[0].point, inf);
    EXPECT_NEAR(old.distance, bruteForceClosest(moved.points, moved.faces, before[0].point, inf).distance, 1e-12);
    EXPECT_GT(old.distance, 1.0);
}

TEST(surfaceSearch, deformedSurfaceMatchesBruteForceAfterMove)
{
    std::mt19937 rng(5);
    const Surface s = twistedCylinder();
    SurfaceSearch search;
    search.build(s.points, s.faces);

    // Bulge the cylinder non-uniformly
    Surface moved = s;
    for (V& p : moved.points)
    {
        const double r = 1 + 0.3*std::sin(2*p.z())*p.x();
        p.x() *= r;
        p.y() *= r;
    }
    search.move(moved.points);
    int sameFace = 0;
    const std::vector<V> queries =
        randomPoints(rng, V(-1.5, -1.5, -0.5), V(1.5, 1.5, 2.5), 500);
    for (const V& q : queries)
    {
        sameFace += expectSameHit
        (
            moved, q, search.closest(q, inf),
            bruteForceClosest(moved.points, moved.faces, q, inf)
        );
    }
    EXPECT_GT(sameFace, 0.5*queries.size());
}

TEST(surfaceSearch, degenerateTrianglesAreLeftOutAndMoveCanRestoreThem)
{
    std::vector<V> p =
    {
        V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0),
        V(3, 0, 0), V(4, 0, 0), V(5, 0, 0)
    };
    const Faces f =
    {
        {0, 1, 2, 3},   // 4 fan triangles
        {0, 1, 2, 2},   // repeated vertex: (2, 2, c) has zero area
        {4, 5, 6}       // collinear: no triangle at all
    };
    SurfaceSearch search;
    search.build(p, f);
    EXPECT_EQ(search.nFaces(), 3);
    EXPECT_EQ(search.nTriangles(), 4 + 3 + 0);

    // Nearest to the collinear face's points is the square's corner
    SearchHit hit = search.closest(V(4, 0, 0.5), inf);
    ASSERT_TRUE(hit.found);
    EXPECT_NE(hit.face, 2);
    EXPECT_NEAR(hit.distance, std::sqrt(9 + 0.25), 1e-14);

    // Lift point 6 off the line: the face becomes a real triangle
    p[6] = V(5, 1, 0);
    search.move(p);
    EXPECT_EQ(search.nTriangles(), 4 + 3 + 1);
    hit = search.closest(V(4, 0, 0.5), inf);
    ASSERT_TRUE(hit.found);
    EXPECT_EQ(hit.face, 2);
    EXPECT_NEAR(hit.distance, 0.5, 1e-15);
}

TEST(surfaceSearch, surfaceWithoutTrianglesFindsNothing)
{
    const std::vector<V> p = {V(0, 0, 0), V(1, 1, 1), V(2, 2, 2)};
    const Faces f = {{0, 1, 2}};
    SurfaceSearch search;
    search.build(p, f);
    EXPECT_EQ(search.nFaces(), 1);
    EXPECT_EQ(search.nTriangles(), 0);
    EXPECT_FALSE(search.closest(V(0, 0, 0), inf).found);
    EXPECT_FALSE(bruteForceClosest(p, f, V(0, 0, 0), inf).found);
    EXPECT_TRUE(search.facesInBox(V(-9, -9, -9), V(9, 9, 9)).empty());
}

TEST(surfaceSearch, facesInBoxOnGrid)
{
    const Surface s = flatGrid(10, 10);
    SurfaceSearch search;
    search.build(s.points, s.faces);

    std::vector<int> expected;
    for (int j = 3; j <= 5; ++j)
    {
        for (int i = 2; i <= 4; ++i)
        {
            expected.push_back(i + 10*j);
        }
    }
    EXPECT_EQ(search.facesInBox(V(2.5, 3.5, -1), V(4.5, 5.5, 1)), expected);

    // The box is closed: a point box on a grid vertex meets its 4 cells
    EXPECT_EQ
    (
        search.facesInBox(V(5, 5, 0), V(5, 5, 0)),
        (std::vector<int>{44, 45, 54, 55})
    );
    // Above the plane, or beside the grid: nothing
    EXPECT_TRUE(search.facesInBox(V(2, 2, 0.1), V(8, 8, 1)).empty());
    EXPECT_TRUE(search.facesInBox(V(10.5, 0, -1), V(12, 10, 1)).empty());
    // Everything
    EXPECT_EQ(int(search.facesInBox(V(-1, -1, -1), V(11, 11, 1)).size()), 100);
}

TEST(surfaceSearch, facesInBoxIsBoundingBoxBroadPhase)
{
    // The box misses the triangle but meets its bounding box: listed
    const std::vector<V> p = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)};
    SurfaceSearch search;
    search.build(p, {{0, 1, 2}});
    EXPECT_EQ(search.facesInBox(V(0.8, 0.8, -1), V(1, 1, 1)), std::vector<int>{0});
    EXPECT_TRUE(search.facesInBox(V(1.01, 0, -1), V(2, 1, 1)).empty());
}

TEST(surfaceSearch, facesInBoxMatchesReferenceOnWavySurface)
{
    std::mt19937 rng(6);
    const Surface s = wavySurface(rng);
    SurfaceSearch search;
    search.build(s.points, s.faces);
    // Boxes from beside to across the surface (|z| <= 0.11)
    std::uniform_real_distribution<double> u(-0.2, 1.2), uz(-0.2, 0.1), size(0.02, 0.3);
    std::size_t total = 0; int nonEmpty = 0;
    for (int k = 0; k < 200; ++k)
    {
        const V lo(u(rng), u(rng), uz(rng));
        const V hi = lo + V(size(rng), size(rng), size(rng));
        const std::vector<int> got = search.facesInBox(lo, hi);
        EXPECT_EQ(got, facesInBoxReference(s, lo, hi));
        total += got.size();
        nonEmpty += !got.empty();
    }
    // Both outcomes occur often, or the test proves little
    EXPECT_GT(nonEmpty, 50);
    EXPECT_LT(nonEmpty, 150);
    EXPECT_GT(total, 500u);
}

TEST(surfaceSearch, movedFromSearchIsEmpty)
{
    const Surface s = flatGrid(3, 3);
    SurfaceSearch a;
    a.build(s.points, s.faces);
    SurfaceSearch b(std::move(a));
    EXPECT_EQ(b.nFaces(), 9);
    EXPECT_EQ(b.closest(V(1.5, 1.5, 2), inf).face, 4);
    EXPECT_EQ(a.nFaces(), 0);
    EXPECT_THROW(a.closest(V(0, 0, 0), inf), std::invalid_argument);

    SurfaceSearch c;
    c = std::move(b);
    EXPECT_EQ(c.closest(V(0.5, 2.5, -1), inf).face, 6);
    // A moved-from search can be built again
    a.build(s.points, s.faces);
    EXPECT_EQ(a.closest(V(2.5, 0.5, 1), inf).face, 2);
}

TEST(surfaceSearch, badInputThrows)
{
    const Surface s = flatGrid(2, 2);   // 9 points
    const V q(0.5, 0.5, 1);

    SurfaceSearch empty;
    expectInvalid([&] { empty.closest(q, inf); }, "before build()");
    expectInvalid([&] { empty.move(s.points); }, "before build()");
    expectInvalid([&] { empty.facesInBox(V(0, 0, 0), V(1, 1, 1)); }, "before build()");

    SurfaceSearch search;
    expectInvalid([&] { search.build(s.points, {{0, 1, 4}, {0, 1}}); }, "face 1 has 2 vertices");
    expectInvalid([&] { search.build(s.points, {{0, 1, 9, 3}}); }, "refers to point 9");
    expectInvalid([&] { search.build(s.points, {{0, -1, 4}}); }, "refers to point -1");
    std::vector<V> nan = s.points;
    nan[4].z() = std::nan("");
    expectInvalid([&] { search.build(nan, s.faces); }, "point 4 is not finite");
    EXPECT_EQ(search.nFaces(), 0);

    // A failed build leaves the previous surface in place
    search.build(s.points, s.faces);
    expectInvalid([&] { search.build(s.points, {{0, 1, 99}}); }, "refers to point 99");
    EXPECT_EQ(search.nFaces(), 4);
    EXPECT_EQ(search.closest(q, inf).face, 0);

    std::vector<V> fewer(s.points.begin(), s.points.end() - 1);
    expectInvalid([&] { search.move(fewer); }, "got 8 points but the surface was built with 9");
    expectInvalid([&] { search.move(nan); }, "not finite");
    EXPECT_NEAR(search.closest(q, inf).distance, 1, 1e-15);

    expectInvalid([&] { search.closest(q, -1); }, "maxDistance");
    expectInvalid([&] { search.closest(q, std::nan("")); }, "maxDistance");
    expectInvalid([&] { search.closest(V(0, inf, 0), 1); }, "not finite");
    expectInvalid([&] { search.facesInBox(V(0, 0, 1), V(1, 1, 0)); }, "lo <= hi");

    expectInvalid([&] { bruteForceClosest(s.points, {{0, 1}}, q, inf); }, "face 0 has 2 vertices");
    expectInvalid([&] { bruteForceClosest(s.points, {{0, 1, 12}}, q, inf); }, "refers to point 12");
    expectInvalid([&] { bruteForceClosest(s.points, s.faces, q, -0.5); }, "maxDistance");
}


// firstHit: the ray finds the face it crosses, not the nearest one. A
// unit cube's bottom face (y = 0) with a point 0.3 inside it and 0.1 from
// its side x = 1: the closest point is on the side, the ray down on the
// bottom at distance 0.3.
TEST(surfaceSearch, firstHitFindsTheCrossedFace)
{
    const std::vector<Eigen::Vector3d> p =
    {
        {0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1},
        {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}
    };
    const std::vector<std::vector<int>> f =
    {
        {0, 1, 2, 3}, {4, 7, 6, 5}, {1, 5, 6, 2}, {0, 3, 7, 4},
        {0, 4, 5, 1}, {3, 2, 6, 7}
    };
    c4f::search::SurfaceSearch s;
    s.build(p, f);
    const Eigen::Vector3d q(0.9, 0.3, 0.5);
    const c4f::search::SearchHit c = s.closest(q, 10);
    ASSERT_TRUE(c.found);
    EXPECT_EQ(c.face, 2);
    EXPECT_NEAR(c.distance, 0.1, 1e-14);

    const c4f::search::SearchHit h = s.firstHit(q, Eigen::Vector3d(0, -2, 0), 10);
    ASSERT_TRUE(h.found);
    EXPECT_EQ(h.face, 0);
    EXPECT_NEAR(h.distance, 0.3, 1e-14);
    EXPECT_NEAR((h.point - Eigen::Vector3d(0.9, 0, 0.5)).norm(), 0, 1e-14);

    // Beyond maxDistance, or away from the surface: nothing
    EXPECT_FALSE(s.firstHit(q, Eigen::Vector3d(0, -1, 0), 0.2).found);
    EXPECT_FALSE
    (
        s.firstHit(Eigen::Vector3d(3, 3, 3), Eigen::Vector3d(1, 0, 0), 10).found
    );

    // Along a face's plane: the segment's end nearer the origin
    const c4f::search::SearchHit e =
        s.firstHit(Eigen::Vector3d(-1, 0, 0.5), Eigen::Vector3d(1, 0, 0), 10);
    ASSERT_TRUE(e.found);
    EXPECT_NEAR(e.distance, 1, 1e-14);

    EXPECT_THROW
    (
        s.firstHit(q, Eigen::Vector3d(0, 0, 0), 1), std::invalid_argument
    );
    EXPECT_THROW
    (
        s.firstHit(q, Eigen::Vector3d(0, -1, 0), -1), std::invalid_argument
    );
}
