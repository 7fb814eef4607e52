/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "surfaceSearch.H"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace c4f
{
namespace search
{

namespace
{

// Plain double arithmetic: the queries are constructions (closest points),
// which no filtered exact kernel would make exact anyway
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using TriangleList = std::vector<Triangle>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleList::const_iterator>;
using Traits = CGAL::AABB_traits<Kernel, Primitive>;
using Tree = CGAL::AABB_tree<Traits>;
using Node = CGAL::AABB_node<Traits>;
using Vector = Eigen::Vector3d;


Point toCgal(const Vector& v)
{
    return Point(v.x(), v.y(), v.z());
}


Vector toEigen(const Point& p)
{
    return Vector(p.x(), p.y(), p.z());
}


//- Triangles of the fan triangulation and the face each came from
struct Triangulation
{
    TriangleList triangles;
    std::vector<int> face;
};


void checkPoints(const std::vector<Vector>& points, const char* caller)
{
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        if (!points[i].allFinite())
        {
            throw std::invalid_argument
            (
                std::string(caller) + ": point " + std::to_string(i)
              + " is not finite"
            );
        }
    }
}


void checkFaces
(
    const std::size_t nPoints,
    const std::vector<std::vector<int>>& faces,
    const char* caller
)
{
    for (std::size_t fi = 0; fi < faces.size(); ++fi)
    {
        const std::vector<int>& f = faces[fi];
        if (f.size() < 3)
        {
            throw std::invalid_argument
            (
                std::string(caller) + ": face " + std::to_string(fi)
              + " has " + std::to_string(f.size())
              + " vertices; a polygon needs at least 3"
            );
        }
        for (const int v : f)
        {
            if (v < 0 || static_cast<std::size_t>(v) >= nPoints)
            {
                throw std::invalid_argument
                (
                    std::string(caller) + ": face " + std::to_string(fi)
                  + " refers to point " + std::to_string(v)
                  + " but there are " + std::to_string(nPoints) + " points"
                );
            }
        }
    }
}


void checkQuery(const Vector& q, const double maxDistance, const char* caller)
{
    if (!q.allFinite())
    {
        throw std::invalid_argument
        (
            std::string(caller) + ": the query point is not finite"
        );
    }
    // Written so that NaN fails too
    if (!(maxDistance >= 0))
    {
        throw std::invalid_argument
        (
            std::string(caller) + ": maxDistance must be >= 0, got "
          + std::to_string(maxDistance)
        );
    }
}


//- Fan triangulation (see the header); the one place that decides which
//  triangles exist, so that the tree and the brute-force reference agree
Triangulation triangulate
(
    const std::vector<Vector>& points,
    const std::vector<std::vector<int>>& faces
)
{
    Triangulation t;
    std::size_t nMax = 0;
    for (const std::vector<int>& f : faces)
    {
        nMax += f.size() == 3 ? 1 : f.size();
    }
    t.triangles.reserve(nMax);
    t.face.reserve(nMax);

    const auto add = [&t](const Triangle& tri, const int fi)
    {
        // Zero area by CGAL's own test: exactly the triangles it would
        // assert on or mis-project
        if (!tri.is_degenerate())
        {
            t.triangles.push_back(tri);
            t.face.push_back(fi);
        }
    };

    for (std::size_t fi = 0; fi < faces.size(); ++fi)
    {
        const std::vector<int>& f = faces[fi];
        const int faceI = static_cast<int>(fi);
        if (f.size() == 3)
        {
            add
            (
                Triangle(toCgal(points[f[0]]), toCgal(points[f[1]]), toCgal(points[f[2]])),
                faceI
            );
            continue;
        }

        Vector centre = Vector::Zero();
        for (const int v : f)
        {
            centre += points[v];
        }
        centre /= static_cast<double>(f.size());
        const Point c = toCgal(centre);

        for (std::size_t i = 0; i < f.size(); ++i)
        {
            const int a = f[i];
            const int b = f[(i + 1) % f.size()];
            add(Triangle(toCgal(points[a]), toCgal(points[b]), c), faceI);
        }
    }
    return t;
}


//- Closest point on segment [a, b] to p
Vector closestOnSegment(const Vector& p, const Vector& a, const Vector& b)
{
    const Vector ab = b - a;
    const double len2 = ab.squaredNorm();
    if (!(len2 > 0))
    {
        return a;
    }
    const double t = std::min(1.0, std::max(0.0, (p - a).dot(ab)/len2));
    return a + t*ab;
}


//- Closest point on triangle (a, b, c) to p: Ericson, Real-Time Collision
//  Detection, sec. 5.1.5. The Voronoi regions of the vertices, then of the
//  edges, are tested with dot products of the edges with p - vertex; what
//  is left is the interior, whose barycentric coordinates are the ratios
//  of the region determinants va, vb, vc.
Vector closestOnTriangle
(
    const Vector& p,
    const Vector& a,
    const Vector& b,
    const Vector& c
)
{
    const Vector ab = b - a;
    const Vector ac = c - a;

    const Vector ap = p - a;
    const double d1 = ab.dot(ap);
    const double d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0)
    {
        return a;
    }

    const Vector bp = p - b;
    const double d3 = ab.dot(bp);
    const double d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3)
    {
        return b;
    }

    const double vc = d1*d4 - d3*d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
    {
        return a + (d1/(d1 - d3))*ab;
    }

    const Vector cp = p - c;
    const double d5 = ab.dot(cp);
    const double d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6)
    {
        return c;
    }

    const double vb = d5*d2 - d1*d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
    {
        return a + (d2/(d2 - d6))*ac;
    }

    const double va = d3*d6 - d5*d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    {
        return b + ((d4 - d3)/((d4 - d3) + (d5 - d6)))*(c - b);
    }

    const double sum = va + vb + vc;
    if (!(sum > 0))
    {
        // Only reachable by round-off on a sliver: its closest point then
        // lies on an edge
        const Vector pab = closestOnSegment(p, a, b);
        const Vector pbc = closestOnSegment(p, b, c);
        const Vector pca = closestOnSegment(p, c, a);
        Vector best = pab;
        if ((p - pbc).squaredNorm() < (p - best).squaredNorm()) best = pbc;
        if ((p - pca).squaredNorm() < (p - best).squaredNorm()) best = pca;
        return best;
    }
    return a + (vb/sum)*ab + (vc/sum)*ac;
}


//- Box query with bounding-box semantics for the primitives too. CGAL's
//  all_intersected_primitives(Bbox_3) tests box against triangle exactly;
//  the contract here is the cheaper, conservative box-against-box test, so
//  the tree is walked with its traversal() hook and these traits, which
//  follow the interface of CGAL's own Listing_primitive_traits.
class BoxOverlapTraits
{
    const TriangleList::const_iterator first_;
    const std::vector<int>& triFace_;
    std::vector<int>& faces_;

public:

    BoxOverlapTraits
    (
        const TriangleList::const_iterator first,
        const std::vector<int>& triFace,
        std::vector<int>& faces
    )
    :
        first_(first),
        triFace_(triFace),
        faces_(faces)
    {}

    bool go_further() const
    {
        return true;
    }

    void intersection(const CGAL::Bbox_3& box, const Primitive& p)
    {
        if (CGAL::do_overlap(box, p.datum().bbox()))
        {
            faces_.push_back(triFace_[p.id() - first_]);
        }
    }

    bool do_intersect(const CGAL::Bbox_3& box, const Node& node) const
    {
        return CGAL::do_overlap(box, node.bbox());
    }
};

} // End anonymous namespace


struct SurfaceSearch::Impl
{
    std::size_t nPoints = 0;
    std::vector<std::vector<int>> faces;

    // The tree's primitives are iterators into triangles: it is rebuilt
    // whenever triangles is replaced, and Impl never moves (heap, pimpl)
    TriangleList triangles;
    std::vector<int> triFace;
    Tree tree;

    void rebuild(Triangulation&& t)
    {
        triangles = std::move(t.triangles);
        triFace = std::move(t.face);
        tree.rebuild(triangles.cbegin(), triangles.cend());
        // Build the k-d tree of hints now rather than lazily on the first
        // query, so that concurrent const queries only read
        tree.accelerate_distance_queries();
    }
};


SurfaceSearch::SurfaceSearch() = default;

SurfaceSearch::~SurfaceSearch() = default;

SurfaceSearch::SurfaceSearch(SurfaceSearch&&) noexcept = default;

SurfaceSearch& SurfaceSearch::operator=(SurfaceSearch&&) noexcept = default;


const SurfaceSearch::Impl& SurfaceSearch::built(const char* caller) const
{
    if (!impl_)
    {
        throw std::invalid_argument
        (
            std::string("SurfaceSearch::") + caller + ": called before build()"
        );
    }
    return *impl_;
}


void SurfaceSearch::build
(
    const std::vector<Vector>& points,
    const std::vector<std::vector<int>>& faces
)
{
    checkPoints(points, "SurfaceSearch::build");
    checkFaces(points.size(), faces, "SurfaceSearch::build");

    // Complete the new state before replacing the old one, so that a throw
    // leaves the previous surface searchable
    auto impl = std::make_unique<Impl>();
    impl->nPoints = points.size();
    impl->faces = faces;
    impl->rebuild(triangulate(points, faces));
    impl_ = std::move(impl);
}


void SurfaceSearch::move(const std::vector<Vector>& points)
{
    built("move");
    Impl& impl = *impl_;
    if (points.size() != impl.nPoints)
    {
        throw std::invalid_argument
        (
            "SurfaceSearch::move: got " + std::to_string(points.size())
          + " points but the surface was built with "
          + std::to_string(impl.nPoints)
        );
    }
    checkPoints(points, "SurfaceSearch::move");

    // A triangle may turn degenerate, or stop being so, as the points
    // move: triangulate afresh rather than update the old triangles
    impl.rebuild(triangulate(points, impl.faces));
}


SearchHit SurfaceSearch::closest(const Vector& q, const double maxDistance) const
{
    const Impl& impl = built("closest");
    checkQuery(q, maxDistance, "SurfaceSearch::closest");

    SearchHit hit;
    if (impl.tree.empty())
    {
        return hit;
    }

    const Tree::Point_and_primitive_id pp =
        impl.tree.closest_point_and_primitive(toCgal(q));
    const Vector p = toEigen(pp.first);
    const double d = (q - p).norm();
    if (d > maxDistance)
    {
        return hit;
    }

    hit.found = true;
    hit.face = impl.triFace[pp.second - impl.triangles.cbegin()];
    hit.point = p;
    hit.distance = d;
    return hit;
}


SearchHit SurfaceSearch::firstHit
(
    const Vector& origin,
    const Vector& direction,
    const double maxDistance
) const
{
    const Impl& impl = built("firstHit");
    checkQuery(origin, maxDistance, "SurfaceSearch::firstHit");
    if (!direction.allFinite() || !(direction.norm() > 0))
    {
        throw std::invalid_argument
        (
            "SurfaceSearch::firstHit: need a finite non-zero direction"
        );
    }

    SearchHit hit;
    if (impl.tree.empty())
    {
        return hit;
    }

    const Kernel::Ray_3 ray
    (
        toCgal(origin),
        Kernel::Vector_3(direction.x(), direction.y(), direction.z())
    );
    const auto res = impl.tree.first_intersection(ray);
    if (!res)
    {
        return hit;
    }

    Vector x;
    if (const Point* p = boost::get<Point>(&res->first))
    {
        x = toEigen(*p);
    }
    else if
    (
        const Kernel::Segment_3* s = boost::get<Kernel::Segment_3>(&res->first)
    )
    {
        const Vector a = toEigen(s->source());
        const Vector b = toEigen(s->target());
        x = (a - origin).norm() <= (b - origin).norm() ? a : b;
    }
    else
    {
        return hit;
    }

    const double d = (x - origin).norm();
    if (d > maxDistance)
    {
        return hit;
    }
    hit.found = true;
    hit.face = impl.triFace[res->second - impl.triangles.cbegin()];
    hit.point = x;
    hit.distance = d;
    return hit;
}


std::vector<int> SurfaceSearch::facesInBox(const Vector& lo, const Vector& hi) const
{
    const Impl& impl = built("facesInBox");
    if (!lo.allFinite() || !hi.allFinite() || (lo.array() > hi.array()).any())
    {
        throw std::invalid_argument
        (
            "SurfaceSearch::facesInBox: need finite lo <= hi in every"
            " component"
        );
    }

    const CGAL::Bbox_3 box(lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z());
    std::vector<int> faces;
    BoxOverlapTraits traits(impl.triangles.cbegin(), impl.triFace, faces);
    impl.tree.traversal(box, traits);

    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    return faces;
}


int SurfaceSearch::nFaces() const
{
    return impl_ ? static_cast<int>(impl_->faces.size()) : 0;
}


int SurfaceSearch::nTriangles() const
{
    return impl_ ? static_cast<int>(impl_->triangles.size()) : 0;
}


SearchHit bruteForceClosest
(
    const std::vector<Vector>& points,
    const std::vector<std::vector<int>>& faces,
    const Vector& q,
    const double maxDistance
)
{
    checkPoints(points, "bruteForceClosest");
    checkFaces(points.size(), faces, "bruteForceClosest");
    checkQuery(q, maxDistance, "bruteForceClosest");

    const Triangulation t = triangulate(points, faces);

    SearchHit hit;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < t.triangles.size(); ++i)
    {
        const Triangle& tri = t.triangles[i];
        const Vector p = closestOnTriangle
        (
            q,
            toEigen(tri.vertex(0)),
            toEigen(tri.vertex(1)),
            toEigen(tri.vertex(2))
        );
        const double d = (q - p).norm();
        if (d < best)
        {
            best = d;
            hit.face = t.face[i];
            hit.point = p;
            hit.distance = d;
        }
    }

    if (t.triangles.empty() || best > maxDistance)
    {
        return SearchHit();
    }
    hit.found = true;
    return hit;
}

} // End namespace search
} // End namespace c4f
