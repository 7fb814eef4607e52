/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "polygonInterpolation.H"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Barycentric_coordinates_2/Mean_value_coordinates_2.h>

#include <exception>
#include <iterator>

namespace
{

using Kernel = CGAL::Simple_cartesian<double>;

std::vector<double> nearestVertex
(
    const c4f::transfer::Polygon& p,
    const Eigen::Vector3d& x
)
{
    std::vector<double> w(p.size(), 0.0);
    size_t best = 0;
    for (size_t i = 1; i < p.size(); ++i)
    {
        if ((p[i] - x).squaredNorm() < (p[best] - x).squaredNorm())
        {
            best = i;
        }
    }
    w[best] = 1;
    return w;
}


//- The weights of a polygon without repeated vertices
std::vector<double> simplePolygonWeights
(
    const c4f::transfer::Polygon& p,
    const Eigen::Vector3d& x
)
{
    using namespace c4f::transfer;

    // The in-plane frame: the longest edge, and the Newell normal crossed
    // with it (counter-clockwise vertices, as the normal is right-handed
    // with their order)
    double longest = 0;
    Eigen::Vector3d e1(Eigen::Vector3d::Zero());
    for (size_t i = 0; i < p.size(); ++i)
    {
        const Eigen::Vector3d e(p[(i + 1) % p.size()] - p[i]);
        if (e.norm() > longest)
        {
            longest = e.norm();
            e1 = e;
        }
    }
    const Plane plane(polygonPlane(p));
    if
    (
        p.size() < 3
     || plane.normal.squaredNorm() == 0
     || areaVector(p).norm() <= 1e-12*longest*longest
    )
    {
        return nearestVertex(p, x);
    }
    e1 -= e1.dot(plane.normal)*plane.normal;
    e1.normalize();
    const Eigen::Vector3d e2(plane.normal.cross(e1));

    std::vector<Kernel::Point_2> poly;
    poly.reserve(p.size());
    for (const Eigen::Vector3d& v : p)
    {
        const Eigen::Vector3d d(v - plane.origin);
        poly.emplace_back(d.dot(e1), d.dot(e2));
    }
    const Eigen::Vector3d dx(x - plane.origin);
    const Kernel::Point_2 q(dx.dot(e1), dx.dot(e2));

    std::vector<double> w;
    w.reserve(p.size());
    try
    {
        CGAL::Barycentric_coordinates::mean_value_coordinates_2
        (
            poly, q, std::back_inserter(w), Kernel()
        );
    }
    catch (const std::exception&)
    {
        // A self-crossing face (CGAL's precondition: a simple polygon)
        return nearestVertex(p, x);
    }

    // Normalised again: CGAL's sum is one to round-off
    double sum = 0;
    for (const double wi : w)
    {
        sum += wi;
    }
    if (w.size() != p.size() || !(std::abs(sum) > 0))
    {
        return nearestVertex(p, x);
    }
    for (double& wi : w)
    {
        wi /= sum;
    }
    return w;
}

} // End anonymous namespace


std::vector<double> c4f::transfer::meanValueCoordinates
(
    const Polygon& p,
    const Eigen::Vector3d& x
)
{
    if (p.empty())
    {
        return {};
    }

    // A vertex repeated next to itself (points merged within a tolerance)
    // makes the polygon non-simple for CGAL, whose precondition would
    // throw: such a vertex takes no weight of its own
    Eigen::Vector3d lo(p.front()), hi(p.front());
    for (const Eigen::Vector3d& v : p)
    {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const double tol = 1e-12*(hi - lo).norm();
    std::vector<size_t> kept;
    kept.reserve(p.size());
    for (size_t i = 0; i < p.size(); ++i)
    {
        if (kept.empty() || (p[i] - p[kept.back()]).norm() > tol)
        {
            kept.push_back(i);
        }
    }
    if (kept.size() > 1 && (p[kept.front()] - p[kept.back()]).norm() <= tol)
    {
        kept.pop_back();
    }
    if (kept.size() == p.size())
    {
        return simplePolygonWeights(p, x);
    }

    Polygon q;
    q.reserve(kept.size());
    for (const size_t i : kept)
    {
        q.push_back(p[i]);
    }
    const std::vector<double> wq(simplePolygonWeights(q, x));
    std::vector<double> w(p.size(), 0.0);
    for (size_t k = 0; k < kept.size(); ++k)
    {
        w[kept[k]] = wq[k];
    }
    return w;
}


// ************************************************************************* //
