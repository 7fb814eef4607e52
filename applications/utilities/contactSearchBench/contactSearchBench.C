/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
-------------------------------------------------------------------------------
Application
    contactSearchBench

Description
    Benchmark of the proximity (closest point) search of contact detection,
    c4f::search::SurfaceSearch (a CGAL AABB tree), against the brute-force
    reference c4f::search::bruteForceClosest and against OpenFOAM's own
    indexedOctree, measured side by side in one run. Needs no case.

    For each size N (option -sizes) the master surface is the height field

        z = 0.05 sin(2 pi x) cos(2 pi y),  (x, y) in [0, 1]^2,

    meshed with n x n quads, n = round(sqrt(N)), and the slave side is N
    query points, uniformly random in (x, y) (fixed seed) and within
    +-band of the surface in z (option -band, default 0.02), so that every
    query has a hit within the search radius (option -radius, default 0.1).
    The queries are i.i.d., so the first k of them are a random sample.

    Measured per size:
      - CGAL: build() time and closest() time per query, over the first
        min(N, maxQueries) queries (option -maxQueries, default 100000;
        0 for all N: at N = 1e6 timing all queries with both trees alone
        takes about 2 minutes on a 2-core machine);
      - brute force: bruteForceClosest() time per query over the first
        -bruteSamples queries (default 200). It triangulates the surface on
        every call, which is part of the measured cost;
      - octree: an indexedOctree<treeDataPrimitivePatch> over the very
        triangles the CGAL tree holds (the same vertex-average fan of every
        quad; face::nearestPoint would fan around the area-weighted centre
        instead, a slightly different surface for a non-planar quad), built
        as triSurfaceSearch builds its tree (bounding box extended by 1e-4,
        maxLevel 10, leaf size 10, duplicity 3, no cached face boxes);
        build time (triangulation included, as in CGAL's build()) and
        findNearest() time per query with the search radius squared, on
        the same queries as CGAL;
      - rebuild: CGAL's tree cannot refit, so move() after a small smooth
        displacement of the points rebuilds it; its time is set against
        the time of the N queries it serves (N times the time per query),
        the rebuild share of one corrector's search.

    Scaling: the log-log slope of the time per query against the number of
    faces, between consecutive sizes and by least squares over all sizes.
    With a fixed band the query distance grows relative to the face size
    (band/h = 0.6 at N = 1e3, 20 at N = 1e6), so more of the tree lies
    within reach of each query; and random query order leaves the tree
    out of cache once it outgrows it. Both lift the slope above that of
    log N (-band 0.0002 shows the second alone).

    Checks: CGAL against brute force on the brute-force sample, CGAL
    against the octree on every timed query, and CGAL after move() against
    brute force on the moved points (option -moveSamples, default 20): a
    mismatch is a different found flag or distances differing by more
    than 1e-10. Faces reported as
    different with agreeing distances (ties on shared edges and vertices)
    are counted for information only.

    Each timed step is repeated until it has run for -minTime seconds
    (default 0.2) and the mean is reported, so small sizes are not timer
    noise. Exits 1 if any check mismatches.

Usage
    contactSearchBench [-sizes '(1000 10000 100000 1000000)']
        [-maxQueries 100000] [-bruteSamples 200] [-moveSamples 20]
        [-band 0.02] [-radius 0.1] [-seed 1] [-minTime 0.2] [-json file]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "PrimitivePatch.H"
#include "triFace.H"
#include "treeBoundBox.H"
#include "indexedOctree.H"
#include "treeDataPrimitivePatch.H"
#include "Random.H"

#include "surfaceSearch.H"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace
{

using Vec = Eigen::Vector3d;
using Points = std::vector<Vec>;
using Faces = std::vector<std::vector<int>>;

using TriPatch =
    Foam::PrimitivePatch<Foam::triFace, Foam::List, const Foam::pointField&>;
using TreeData = Foam::treeDataPrimitivePatch<TriPatch>;
using Octree = Foam::indexedOctree<TreeData>;

constexpr double pi = 3.14159265358979323846;
constexpr double amplitude = 0.05;
constexpr double tolerance = 1e-10;


double height(const double x, const double y)
{
    return amplitude*std::sin(2*pi*x)*std::cos(2*pi*y);
}


//- splitmix64: a small generator whose sequence, unlike that of the
//  <random> distributions, is fixed by its definition on every platform
class Rng
{
    std::uint64_t state_;

public:

    explicit Rng(const std::uint64_t seed)
    :
        state_(seed)
    {}

    std::uint64_t next()
    {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30))*0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27))*0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }

    //- Uniform in [0, 1)
    double uniform()
    {
        return static_cast<double>(next() >> 11)*0x1.0p-53;
    }
};


//- The wavy master surface, n x n quads (counter-clockwise seen from +z)
void makeSurface(const int n, Points& points, Faces& faces)
{
    points.clear();
    faces.clear();
    points.reserve(std::size_t(n + 1)*(n + 1));
    faces.reserve(std::size_t(n)*n);
    for (int j = 0; j <= n; ++j)
    {
        for (int i = 0; i <= n; ++i)
        {
            const double x = double(i)/n;
            const double y = double(j)/n;
            points.emplace_back(x, y, height(x, y));
        }
    }
    const auto id = [n](const int i, const int j) { return j*(n + 1) + i; };
    for (int j = 0; j < n; ++j)
    {
        for (int i = 0; i < n; ++i)
        {
            faces.push_back
            (
                {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}
            );
        }
    }
}


//- nQuery slave points within +-band of the surface
Points makeQueries(const long nQuery, const double band, Rng& rng)
{
    Points q;
    q.reserve(nQuery);
    for (long k = 0; k < nQuery; ++k)
    {
        const double x = rng.uniform();
        const double y = rng.uniform();
        const double dz = band*(2*rng.uniform() - 1);
        q.emplace_back(x, y, height(x, y) + dz);
    }
    return q;
}


//- A small smooth displacement (at most ~1e-3), as one load step might give
Points displaced(const Points& points)
{
    Points moved(points);
    for (Vec& p : moved)
    {
        const double x = p.x();
        const double y = p.y();
        p += 1e-3*Vec
        (
            std::sin(2*pi*y),
            std::cos(2*pi*x),
            0.5*std::sin(2*pi*(x + y))
        );
    }
    return moved;
}


//- The octree side: the fan triangles of every polygon, as OpenFOAM types
struct OctreeSurface
{
    Foam::pointField points;
    std::vector<int> triFace;
    std::unique_ptr<TriPatch> patch;
    std::unique_ptr<Octree> tree;

    void build(const Points& pts, const Faces& faces)
    {
        tree.reset();
        patch.reset();

        const Foam::label nPoints = pts.size();
        std::size_t nTri = 0;
        for (const std::vector<int>& f : faces)
        {
            nTri += f.size() == 3 ? 1 : f.size();
        }

        points.setSize(nPoints + Foam::label(faces.size()));
        for (Foam::label i = 0; i < nPoints; ++i)
        {
            points[i] = Foam::point(pts[i].x(), pts[i].y(), pts[i].z());
        }

        Foam::List<Foam::triFace> tris(static_cast<Foam::label>(nTri));
        triFace.resize(nTri);
        Foam::label t = 0;
        for (std::size_t fi = 0; fi < faces.size(); ++fi)
        {
            const std::vector<int>& f = faces[fi];
            const Foam::label c = nPoints + Foam::label(fi);
            if (f.size() == 3)
            {
                points[c] = points[f[0]];  // unused
                triFace[t] = int(fi);
                tris[t++] = Foam::triFace(f[0], f[1], f[2]);
                continue;
            }
            // The vertex average, computed as surfaceSearch.C does
            Vec centre = Vec::Zero();
            for (const int v : f)
            {
                centre += pts[v];
            }
            centre /= static_cast<double>(f.size());
            points[c] = Foam::point(centre.x(), centre.y(), centre.z());
            for (std::size_t i = 0; i < f.size(); ++i)
            {
                triFace[t] = int(fi);
                tris[t++] = Foam::triFace(f[i], f[(i + 1) % f.size()], c);
            }
        }
        patch.reset(new TriPatch(std::move(tris), points));

        // As triSurfaceSearch::tree()
        Foam::treeBoundBox bb(points);
        Foam::Random rndGen(65431);
        bb = bb.extend(rndGen, 1e-4);
        bb.min() -= Foam::point::uniform(Foam::ROOTVSMALL);
        bb.max() += Foam::point::uniform(Foam::ROOTVSMALL);

        tree.reset
        (
            new Octree
            (
                TreeData(false, *patch, Octree::perturbTol()),
                bb,
                10,     // maxLevel
                10,     // leaf size
                3.0     // duplicity
            )
        );
    }
};


//- Mean seconds per call of f, calling it until minTime has passed (at
//  least once)
template<class F>
double timed(F&& f, const double minTime)
{
    using clock = std::chrono::steady_clock;
    double total = 0;
    long reps = 0;
    do
    {
        const auto t0 = clock::now();
        f();
        total += std::chrono::duration<double>(clock::now() - t0).count();
        ++reps;
    } while (total < minTime);
    return total/reps;
}


struct Hit
{
    bool found = false;
    int face = -1;
    double distance = 0;
};


//- Mismatch and (informative) face-difference counts of b against a
struct Agreement
{
    long compared = 0;
    long mismatches = 0;
    long faceDiffers = 0;
    double maxDiff = 0;

    void add(const Hit& a, const Hit& b)
    {
        ++compared;
        if (a.found != b.found)
        {
            ++mismatches;
            return;
        }
        if (!a.found)
        {
            return;
        }
        const double d = std::abs(a.distance - b.distance);
        maxDiff = std::max(maxDiff, d);
        if (!(d <= tolerance))
        {
            ++mismatches;
        }
        else if (a.face != b.face)
        {
            ++faceDiffers;
        }
    }
};


Hit toHit(const c4f::search::SearchHit& h)
{
    return Hit{h.found, h.face, h.distance};
}


struct Row
{
    long nRequested = 0;
    long nFaces = 0;
    long nTriangles = 0;
    long nQueries = 0;      // slave points N
    long nTimed = 0;        // of which timed with CGAL and the octree
    long nBrute = 0;
    long nMoveCheck = 0;

    double buildCgal = 0;       // [s]
    double queryCgal = 0;       // [s] per query
    double queryBrute = 0;      // [s] per query
    double buildOctree = 0;     // [s]
    double queryOctree = 0;     // [s] per query
    double rebuildCgal = 0;     // [s]

    Agreement brute;
    Agreement octree;
    Agreement moved;
};


Row runSize
(
    const long nRequested,
    const long nTimedMax,
    const long nBruteMax,
    const long nMoveMax,
    const double band,
    const double radius,
    const std::uint64_t seed,
    const double minTime
)
{
    Row row;
    row.nRequested = nRequested;

    const int n = std::max(1, int(std::lround(std::sqrt(double(nRequested)))));
    Points points;
    Faces faces;
    makeSurface(n, points, faces);
    row.nFaces = faces.size();
    row.nQueries = nRequested;
    row.nTimed = nTimedMax > 0 ? std::min(nTimedMax, nRequested) : nRequested;
    row.nBrute = std::min(nBruteMax, row.nTimed);
    row.nMoveCheck = std::min(nMoveMax, row.nTimed);

    // The queries are i.i.d.: the first nTimed of the N slave points are a
    // random sample of them, and the first nBrute a sample of those
    Rng rng(seed + std::uint64_t(nRequested));
    const Points queries = makeQueries(row.nTimed, band, rng);

    // 1. CGAL AABB tree
    c4f::search::SurfaceSearch search;
    row.buildCgal = timed([&]() { search.build(points, faces); }, minTime);
    row.nTriangles = search.nTriangles();

    std::vector<Hit> cgal(queries.size());
    row.queryCgal = timed
    (
        [&]()
        {
            for (std::size_t k = 0; k < queries.size(); ++k)
            {
                cgal[k] = toHit(search.closest(queries[k], radius));
            }
        },
        minTime
    )/row.nTimed;

    // 2. Brute force on a sample
    std::vector<Hit> brute(row.nBrute);
    row.queryBrute = timed
    (
        [&]()
        {
            for (long k = 0; k < row.nBrute; ++k)
            {
                brute[k] = toHit
                (
                    c4f::search::bruteForceClosest
                    (
                        points, faces, queries[k], radius
                    )
                );
            }
        },
        minTime
    )/std::max(row.nBrute, 1L);
    for (long k = 0; k < row.nBrute; ++k)
    {
        row.brute.add(cgal[k], brute[k]);
    }

    // 3. OpenFOAM indexedOctree over the same triangles
    {
        OctreeSurface oct;
        row.buildOctree = timed([&]() { oct.build(points, faces); }, minTime);

        const double r2 = radius*radius;
        std::vector<Hit> octHits(queries.size());
        row.queryOctree = timed
        (
            [&]()
            {
                for (std::size_t k = 0; k < queries.size(); ++k)
                {
                    const Foam::point s
                    (
                        queries[k].x(), queries[k].y(), queries[k].z()
                    );
                    const Foam::pointIndexHit h = oct.tree->findNearest(s, r2);
                    Hit& o = octHits[k];
                    o.found = h.hit();
                    o.face = h.hit() ? oct.triFace[h.index()] : -1;
                    o.distance = h.hit() ? Foam::mag(s - h.hitPoint()) : 0;
                }
            },
            minTime
        )/row.nTimed;
        for (std::size_t k = 0; k < queries.size(); ++k)
        {
            row.octree.add(cgal[k], octHits[k]);
        }
    }

    // 4. Rebuild after a small displacement (no refit in CGAL's tree)
    const Points moved = displaced(points);
    row.rebuildCgal = timed([&]() { search.move(moved); }, minTime);
    for (long k = 0; k < row.nMoveCheck; ++k)
    {
        row.moved.add
        (
            toHit(search.closest(queries[k], radius)),
            toHit(c4f::search::bruteForceClosest(moved, faces, queries[k], radius))
        );
    }

    return row;
}


//- log-log slope of y against x between two points
double slope(const double x0, const double y0, const double x1, const double y1)
{
    return std::log(y1/y0)/std::log(x1/x0);
}


//- Least-squares log-log slope over all rows (NaN for fewer than 2)
template<class Y>
double fitSlope(const std::vector<Row>& rows, Y y)
{
    if (rows.size() < 2)
    {
        return std::nan("");
    }
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double m = rows.size();
    for (const Row& r : rows)
    {
        const double lx = std::log(double(r.nFaces));
        const double ly = std::log(y(r));
        sx += lx; sy += ly; sxx += lx*lx; sxy += lx*ly;
    }
    const double den = m*sxx - sx*sx;
    return den > 0 ? (m*sxy - sx*sy)/den : std::nan("");
}


std::string jsonNumber(const double v)
{
    if (!std::isfinite(v))
    {
        return "null";
    }
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.9g", v);
    return buf;
}


std::string jsonAgreement(const Agreement& a)
{
    return "{\"compared\": " + std::to_string(a.compared)
      + ", \"mismatches\": " + std::to_string(a.mismatches)
      + ", \"faceDiffers\": " + std::to_string(a.faceDiffers)
      + ", \"maxDistanceDiff\": " + jsonNumber(a.maxDiff) + "}";
}


} // End anonymous namespace


int main(int argc, char *argv[])
{
    using namespace Foam;

    argList::addNote
    (
        "Benchmark of the contact proximity search: CGAL AABB tree"
        " (c4f::search::SurfaceSearch) against brute force and OpenFOAM's"
        " indexedOctree on a wavy quad surface. Needs no case."
    );
    argList::noBanner();
    argList::noParallel();
    argList::noFunctionObjects();
    argList::noJobInfo();
    argList::noCheckProcessorDirectories();
    argList::removeOption("case");

    argList::addOption
    (
        "sizes", "list",
        "Surface sizes N (quads ~ N, queries = N);"
        " default '(1000 10000 100000 1000000)'"
    );
    argList::addOption
    (
        "bruteSamples", "n",
        "Queries timed and checked by brute force per size (default 200)"
    );
    argList::addOption
    (
        "moveSamples", "n",
        "Queries checked by brute force after move() (default 20)"
    );
    argList::addOption
    (
        "maxQueries", "n",
        "Time CGAL and the octree on at most this many of the N queries"
        " (default 100000; 0: all N)"
    );
    argList::addOption
    (
        "band", "dz",
        "Query points lie within +-dz of the surface in z (default 0.02)"
    );
    argList::addOption("radius", "r", "Search radius (default 0.1)");
    argList::addOption("seed", "n", "Seed of the query points (default 1)");
    argList::addOption
    (
        "minTime", "s",
        "Repeat each timed step until it has run this long, report the mean"
        " (default 0.2)"
    );
    argList::addOption("json", "file", "Also write the numbers as JSON");

    argList args(argc, argv);

    labelList sizes({1000, 10000, 100000, 1000000});
    args.readListIfPresent("sizes", sizes);
    const label nBrute = args.getOrDefault<label>("bruteSamples", 200);
    const label nMove = args.getOrDefault<label>("moveSamples", 20);
    const label nTimedMax = args.getOrDefault<label>("maxQueries", 100000);
    const scalar band = args.getOrDefault<scalar>("band", 0.02);
    const scalar radius = args.getOrDefault<scalar>("radius", 0.1);
    const label seed = args.getOrDefault<label>("seed", 1);
    const scalar minTime = args.getOrDefault<scalar>("minTime", 0.2);

    for (const label n : sizes)
    {
        if (n < 1)
        {
            FatalErrorInFunction
                << "-sizes: every size must be >= 1, got " << sizes
                << exit(FatalError);
        }
    }
    if
    (
        nBrute < 1 || nMove < 0 || nTimedMax < 0 || !(band >= 0)
     || !(radius > band) || !(minTime >= 0)
    )
    {
        FatalErrorInFunction
            << "need -bruteSamples >= 1, -moveSamples >= 0, -maxQueries >= 0,"
            << " -band >= 0, -radius > band (every query must find the"
            << " surface) and -minTime >= 0"
            << exit(FatalError);
    }

    std::printf
    (
        "contactSearchBench: z = %g sin(2 pi x) cos(2 pi y) on the unit"
        " square, queries within +-%g, radius %g,\n"
        "  N queries per size, of which CGAL and octree time %s and brute"
        " force times %ld,\n"
        "  every timed step repeated for >= %g s (mean), 1 thread"
        " (%u hardware)\n\n",
        amplitude, band, radius,
        nTimedMax > 0
      ? ("at most " + std::to_string(long(nTimedMax))).c_str()
      : "all",
        long(nBrute), minTime,
        std::thread::hardware_concurrency()
    );
    std::fflush(stdout);

    std::vector<Row> rows;
    for (const label n : sizes)
    {
        const auto t0 = std::chrono::steady_clock::now();
        rows.push_back(runSize(n, nTimedMax, nBrute, nMove, band, radius, seed, minTime));
        std::printf
        (
            "  N = %ld done in %.1f s\n", long(n),
            std::chrono::duration<double>
            (
                std::chrono::steady_clock::now() - t0
            ).count()
        );
        std::fflush(stdout);
    }

    // Table 1: times
    std::printf
    (
        "\n%9s %9s %8s %11s %11s %12s %12s %12s %11s %12s\n",
        "N", "faces", "timed", "build CGAL", "query CGAL", "query brute",
        "build octree", "query octree", "brute/CGAL", "octree/CGAL"
    );
    std::printf
    (
        "%9s %9s %8s %11s %11s %12s %12s %12s %11s %12s\n",
        "", "", "queries", "[ms]", "[us]", "[us]", "[ms]", "[us]", "(query)", "(query)"
    );
    for (const Row& r : rows)
    {
        std::printf
        (
            "%9ld %9ld %8ld %11.3f %11.3f %12.2f %12.3f %12.3f %11.1f %12.2f\n",
            r.nRequested, r.nFaces, r.nTimed, 1e3*r.buildCgal, 1e6*r.queryCgal,
            1e6*r.queryBrute, 1e3*r.buildOctree, 1e6*r.queryOctree,
            r.queryBrute/r.queryCgal, r.queryOctree/r.queryCgal
        );
    }

    // Table 2: scaling, rebuild share, checks
    std::printf
    (
        "\n%9s %23s %10s %11s %9s %12s %12s %10s\n",
        "N", "query slope vs prev N", "rebuild", "N queries", "rebuild",
        "brute", "octree", "move"
    );
    std::printf
    (
        "%9s %7s %7s %7s %10s %11s %9s %12s %12s %10s\n",
        "", "CGAL", "octree", "brute", "[ms]", "[ms]", "share",
        "mismatch", "mismatch", "mismatch"
    );
    long mismatches = 0;
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        const Row& r = rows[i];
        char sc[16] = "-", so[16] = "-", sb[16] = "-";
        if (i > 0 && rows[i - 1].nFaces != r.nFaces)
        {
            const Row& p = rows[i - 1];
            const double x0 = p.nFaces, x1 = r.nFaces;
            std::snprintf(sc, sizeof(sc), "%.2f", slope(x0, p.queryCgal, x1, r.queryCgal));
            std::snprintf(so, sizeof(so), "%.2f", slope(x0, p.queryOctree, x1, r.queryOctree));
            std::snprintf(sb, sizeof(sb), "%.2f", slope(x0, p.queryBrute, x1, r.queryBrute));
        }
        const double nq = r.nQueries*r.queryCgal;
        char b[32], o[32], m[32];
        std::snprintf(b, sizeof(b), "%ld/%ld", r.brute.mismatches, r.brute.compared);
        std::snprintf(o, sizeof(o), "%ld/%ld", r.octree.mismatches, r.octree.compared);
        std::snprintf(m, sizeof(m), "%ld/%ld", r.moved.mismatches, r.moved.compared);
        std::printf
        (
            "%9ld %7s %7s %7s %10.3f %11.3f %8.1f%% %12s %12s %10s\n",
            r.nRequested, sc, so, sb, 1e3*r.rebuildCgal, 1e3*nq,
            100*r.rebuildCgal/(r.rebuildCgal + nq), b, o, m
        );
        mismatches +=
            r.brute.mismatches + r.octree.mismatches + r.moved.mismatches;
    }

    const double fitCgal =
        fitSlope(rows, [](const Row& r) { return r.queryCgal; });
    const double fitOctree =
        fitSlope(rows, [](const Row& r) { return r.queryOctree; });
    const double fitBrute =
        fitSlope(rows, [](const Row& r) { return r.queryBrute; });
    if (rows.size() > 1)
    {
        std::printf
        (
            "\nquery time ~ N^s, least squares over all sizes:"
            " CGAL s = %.2f, octree s = %.2f, brute s = %.2f\n",
            fitCgal, fitOctree, fitBrute
        );
    }
    std::printf("\n");

    long faceDiffers = 0;
    double maxDiff = 0;
    for (const Row& r : rows)
    {
        faceDiffers += r.brute.faceDiffers + r.octree.faceDiffers
          + r.moved.faceDiffers;
        maxDiff = std::max
        (
            {maxDiff, r.brute.maxDiff, r.octree.maxDiff, r.moved.maxDiff}
        );
    }
    std::printf
    (
        "checks (|distance difference| <= %g, same found flag):"
        " %ld mismatches; max |distance difference| %.3g;"
        " %ld ties resolved to another face (not mismatches)\n",
        tolerance, mismatches, maxDiff, faceDiffers
    );

    if (args.found("json"))
    {
        const fileName file = args.get<fileName>("json");
        std::ofstream os(file);
        os  << "{\n  \"band\": " << jsonNumber(band)
            << ",\n  \"radius\": " << jsonNumber(radius)
            << ",\n  \"tolerance\": " << jsonNumber(tolerance)
            << ",\n  \"minTime\": " << jsonNumber(minTime)
            << ",\n  \"hardwareThreads\": "
            << std::thread::hardware_concurrency()
            << ",\n  \"sizes\": [\n";
        for (std::size_t i = 0; i < rows.size(); ++i)
        {
            const Row& r = rows[i];
            os  << "    {\"N\": " << r.nRequested
                << ", \"faces\": " << r.nFaces
                << ", \"triangles\": " << r.nTriangles
                << ", \"queries\": " << r.nQueries
                << ", \"timedQueries\": " << r.nTimed
                << ", \"bruteSamples\": " << r.nBrute
                << ",\n     \"buildCgal_ms\": " << jsonNumber(1e3*r.buildCgal)
                << ", \"queryCgal_us\": " << jsonNumber(1e6*r.queryCgal)
                << ", \"queryBrute_us\": " << jsonNumber(1e6*r.queryBrute)
                << ",\n     \"buildOctree_ms\": "
                << jsonNumber(1e3*r.buildOctree)
                << ", \"queryOctree_us\": " << jsonNumber(1e6*r.queryOctree)
                << ", \"rebuildCgal_ms\": " << jsonNumber(1e3*r.rebuildCgal)
                << ", \"queriesCgal_ms\": "
                << jsonNumber(1e3*r.nQueries*r.queryCgal)
                << ",\n     \"brute\": " << jsonAgreement(r.brute)
                << ",\n     \"octree\": " << jsonAgreement(r.octree)
                << ",\n     \"moved\": " << jsonAgreement(r.moved)
                << "}" << (i + 1 < rows.size() ? "," : "") << "\n";
        }
        os  << "  ],\n  \"slope\": {\"cgal\": " << jsonNumber(fitCgal)
            << ", \"octree\": " << jsonNumber(fitOctree)
            << ", \"brute\": " << jsonNumber(fitBrute) << "},\n"
            << "  \"mismatches\": " << mismatches << "\n}\n";
        if (!os)
        {
            FatalErrorInFunction
                << "cannot write " << file << exit(FatalError);
        }
        std::printf("wrote %s\n", file.c_str());
    }

    return mismatches ? 1 : 0;
}


// ************************************************************************* //
