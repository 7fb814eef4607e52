/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "polygonOverlap.H"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace c4f
{
namespace transfer
{

namespace
{

Eigen::Vector3d vertexAverage(const Polygon& p)
{
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& x : p)
    {
        c += x;
    }
    return c/double(p.size());
}


//- Diagonal of the bounding box of both polygons: the length scale of
//  the tolerances, so that they follow the geometry and not its units
double boxDiagonal(const Polygon& a, const Polygon& b = Polygon())
{
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL);
    Eigen::Vector3d hi = Eigen::Vector3d::Constant(-HUGE_VAL);
    for (const Polygon* p : {&a, &b})
    {
        for (const Eigen::Vector3d& x : *p)
        {
            lo = lo.cwiseMin(x);
            hi = hi.cwiseMax(x);
        }
    }
    return (a.empty() && b.empty()) ? 0.0 : (hi - lo).norm();
}

} // End anonymous namespace


Eigen::Vector3d areaVector(const Polygon& p)
{
    Eigen::Vector3d A = Eigen::Vector3d::Zero();
    if (p.size() < 3)
    {
        return A;
    }

    // About the vertex average rather than the origin: the cross products
    // then stay of the face's own size, so a small face far from the
    // origin loses no digits to cancellation
    const Eigen::Vector3d c = vertexAverage(p);
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        A += (p[i] - c).cross(p[(i + 1) % n] - c);
    }
    return 0.5*A;
}


Plane polygonPlane(const Polygon& p)
{
    Plane plane;
    plane.origin =
        p.empty() ? Eigen::Vector3d::Zero().eval() : vertexAverage(p);
    const Eigen::Vector3d A = areaVector(p);
    const double mag = A.norm();
    plane.normal = mag > 0 ? (A/mag).eval() : Eigen::Vector3d::Zero().eval();
    return plane;
}


double polygonArea(const Polygon& p)
{
    return areaVector(p).norm();
}


Eigen::Vector3d polygonCentroid(const Polygon& p)
{
    if (p.empty())
    {
        return Eigen::Vector3d::Zero();
    }
    const Eigen::Vector3d c = vertexAverage(p);
    const Eigen::Vector3d A = areaVector(p);
    const double mag = A.norm();
    if (!(mag > 0))
    {
        return c;
    }
    const Eigen::Vector3d n = A/mag;

    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double area = 0;
    const std::size_t nv = p.size();
    for (std::size_t i = 0; i < nv; ++i)
    {
        const Eigen::Vector3d& a = p[i];
        const Eigen::Vector3d& b = p[(i + 1) % nv];
        const double ai = 0.5*(a - c).cross(b - c).dot(n);
        sum += ai*(c + a + b)/3.0;
        area += ai;
    }
    return sum/area;
}


Polygon projectOntoPlane(const Polygon& p, const Plane& plane)
{
    Polygon q;
    q.reserve(p.size());
    for (const Eigen::Vector3d& x : p)
    {
        q.push_back(x - (x - plane.origin).dot(plane.normal)*plane.normal);
    }
    return q;
}


Polygon clipConvex
(
    const Polygon& subject,
    const Polygon& clip,
    const Eigen::Vector3d& planeNormal,
    const double relTol
)
{
    if (subject.size() < 3 || clip.size() < 3)
    {
        return Polygon();
    }
    const double nMag = planeNormal.norm();
    if (!(nMag > 0))
    {
        return Polygon();
    }

    const double L = boxDiagonal(subject, clip);
    const double tol = relTol*L;

    // Orient the normal so that the clip polygon runs counter-clockwise
    // about it; its interior is then to the left of every edge whichever
    // way the caller's faces are numbered
    Eigen::Vector3d n = planeNormal/nMag;
    const double clipArea = areaVector(clip).dot(n);
    if (std::abs(clipArea) <= relTol*L*L)
    {
        // A clip polygon seen edge-on has no interior in this plane
        return Polygon();
    }
    if (clipArea < 0)
    {
        n = -n;
    }

    Polygon out = subject;
    Polygon in;
    std::vector<double> dist;
    std::vector<int> side;
    const std::size_t nClip = clip.size();

    for (std::size_t k = 0; k < nClip; ++k)
    {
        const Eigen::Vector3d& a = clip[k];
        const Eigen::Vector3d e = clip[(k + 1) % nClip] - a;
        const double len = e.norm();
        if (len <= tol)
        {
            // A repeated clip vertex bounds nothing
            continue;
        }
        const Eigen::Vector3d inward = n.cross(e)/len;

        in.swap(out);
        out.clear();
        const std::size_t m = in.size();
        dist.resize(m);
        side.resize(m);
        for (std::size_t i = 0; i < m; ++i)
        {
            dist[i] = (in[i] - a).dot(inward);
            // Three states, not two: a vertex within tol of the edge is
            // kept as it is and never paired with an intersection point,
            // so touching faces cannot produce slivers or near-duplicate
            // vertices from round-off
            side[i] = dist[i] > tol ? 1 : (dist[i] < -tol ? -1 : 0);
        }

        for (std::size_t i = 0; i < m; ++i)
        {
            const std::size_t j = (i + m - 1) % m;
            const auto cross = [&]()
            {
                // Strictly opposite sides, so the denominator is > 2 tol
                const double t = dist[j]/(dist[j] - dist[i]);
                return Eigen::Vector3d(in[j] + t*(in[i] - in[j]));
            };

            if (side[i] >= 0)
            {
                if (side[j] < 0 && side[i] > 0)
                {
                    out.push_back(cross());
                }
                out.push_back(in[i]);
            }
            else if (side[j] > 0)
            {
                out.push_back(cross());
            }
        }

        if (out.size() < 3)
        {
            return Polygon();
        }
    }

    return out;
}


Polygon overlapPolygon
(
    const Polygon& slave,
    const Polygon& master,
    const double relTol
)
{
    if (slave.size() < 3 || master.size() < 3)
    {
        return Polygon();
    }

    const Plane plane = polygonPlane(master);
    if (plane.normal.squaredNorm() == 0)
    {
        return Polygon();
    }

    const Polygon s = projectOntoPlane(slave, plane);

    // An edge-on slave projects onto a segment; clipping it would leave a
    // round-off-sized area instead of the exact zero
    const double Ls = boxDiagonal(slave);
    if (polygonArea(s) <= relTol*Ls*Ls)
    {
        return Polygon();
    }

    // Flattening a warped master onto its mean plane keeps the clip edges
    // in the plane in which the in/out distances are measured
    return clipConvex(s, projectOntoPlane(master, plane), plane.normal, relTol);
}


double overlapArea
(
    const Polygon& slave,
    const Polygon& master,
    const double relTol
)
{
    return polygonArea(overlapPolygon(slave, master, relTol));
}


std::vector<double> conservativeWeights(const std::vector<double>& overlaps)
{
    double sum = 0;
    for (const double a : overlaps)
    {
        sum += a;
    }
    if (!(sum > 0) || !std::isfinite(sum))
    {
        return std::vector<double>();
    }

    std::vector<double> w(overlaps.size());
    double wSum = 0;
    for (std::size_t j = 0; j < w.size(); ++j)
    {
        w[j] = overlaps[j]/sum;
        wSum += w[j];
    }

    // Each division rounds on its own, so the weights can miss 1 by a few
    // ulps; the largest weight takes the residual, where it is relatively
    // smallest, and the transferred total then equals the slave force to
    // round-off however many candidates share it
    const std::size_t jMax =
        std::max_element(w.begin(), w.end()) - w.begin();
    w[jMax] += 1.0 - wSum;
    return w;
}

bool projectsInside
(
    const Eigen::Vector3d& p,
    const Polygon& convex,
    const double relTol
)
{
    if (convex.size() < 3)
    {
        return false;
    }
    const Eigen::Vector3d A = areaVector(convex);
    const double mag = A.norm();
    const double L = boxDiagonal(convex);
    if (!(mag > relTol*L*L))
    {
        return false;
    }

    // The Newell vector orients the polygon counter-clockwise about n, so
    // the interior lies to the left of every edge; the normal component
    // of p drops out of each triple product
    const Eigen::Vector3d n = A/mag;
    const double tol = relTol*L*L;
    const std::size_t nv = convex.size();
    for (std::size_t i = 0; i < nv; ++i)
    {
        const Eigen::Vector3d& a = convex[i];
        const Eigen::Vector3d& b = convex[(i + 1) % nv];
        if ((b - a).cross(p - a).dot(n) < -tol)
        {
            return false;
        }
    }
    return true;
}


} // End namespace transfer
} // End namespace c4f
