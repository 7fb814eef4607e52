/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "analyticSurface.H"

#include <cmath>
#include <stdexcept>
#include <string>

namespace c4f
{
namespace rigid
{

namespace
{

// An offset from the centre or axis at most this in every component is
// taken as none: its direction would be rounding noise, and squaring it
// would underflow to a zero length and a 0/0 normal
constexpr double degenerateOffset = 1e-300;

// |v| scaled by its largest component first, so that the square of
// neither a 1e-200 offset nor a 1e200 normal leaves the double range
double safeNorm(const Eigen::Vector3d& v, const double m)
{
    return m > 0 ? m*(v/m).norm() : 0.0;
}

Eigen::Vector3d unitOrThrow(const Eigen::Vector3d& v, const char* what)
{
    if (!v.allFinite())
    {
        throw std::invalid_argument(std::string(what) + " is not finite");
    }
    const double m = v.cwiseAbs().maxCoeff();
    if (!(m > 0))
    {
        throw std::invalid_argument(std::string(what) + " is zero");
    }
    const Eigen::Vector3d u = v/m;
    return u/u.norm();
}

void checkRadius(const double R)
{
    // Also rejects NaN; an infinite R would make every gap inf - inf
    if (!(R > 0) || !std::isfinite(R))
    {
        throw std::invalid_argument("radius must be positive and finite");
    }
}

// Split a radial offset into length and direction; false (and no
// direction) where it is too small to have one
bool radialDirection(const Eigen::Vector3d& d, double& r, Eigen::Vector3d& u)
{
    const double m = d.cwiseAbs().maxCoeff();
    r = safeNorm(d, m);
    if (!(m > degenerateOffset))
    {
        return false;
    }
    u = d/r;
    return true;
}

// Point, normal and gap of a sphere or cylinder from the closest point of
// its centre or axis, o, and the unit radial direction u from there
SurfacePoint onRoundSurface
(
    const Eigen::Vector3d& o,
    const Eigen::Vector3d& u,
    const double r,
    const double R,
    const bool inside,
    const bool valid
)
{
    SurfacePoint p;
    p.point = o + R*u;
    p.normal = inside ? Eigen::Vector3d(-u) : u;
    p.gap = inside ? R - r : r - R;
    p.valid = valid;
    return p;
}

} // End anonymous namespace


SurfacePoint closestOnPlane
(
    const Eigen::Vector3d& x,
    const Eigen::Vector3d& p0,
    const Eigen::Vector3d& n
)
{
    SurfacePoint p;
    p.normal = unitOrThrow(n, "plane normal");
    p.gap = (x - p0).dot(p.normal);
    p.point = x - p.gap*p.normal;
    p.valid = true;
    return p;
}


SurfacePoint closestOnSphere
(
    const Eigen::Vector3d& x,
    const Eigen::Vector3d& c,
    const double R,
    const bool inside
)
{
    checkRadius(R);
    double r;
    Eigen::Vector3d u;
    const bool valid = radialDirection(x - c, r, u);
    if (!valid)
    {
        u = Eigen::Vector3d::UnitY();
    }
    return onRoundSurface(c, u, r, R, inside, valid);
}


SurfacePoint closestOnCylinder
(
    const Eigen::Vector3d& x,
    const Eigen::Vector3d& a,
    const Eigen::Vector3d& e,
    const double R,
    const bool inside
)
{
    checkRadius(R);
    const Eigen::Vector3d t = unitOrThrow(e, "cylinder axis");
    const Eigen::Vector3d d = x - a;
    const Eigen::Vector3d o = a + d.dot(t)*t;

    // Projected twice, and kept only if the second pass did not cancel it
    // too (Kahan's "twice is enough" for Gram-Schmidt, in Parlett, The
    // Symmetric Eigenvalue Problem, 1980): near the axis the first pass
    // leaves a vector of the rounding of |d|, with an axial part as large
    // as its radial one; the second removes that part to eps of the rest,
    // so that the normal is across the axis and the point on the surface.
    // A second cancellation means the first result was all axial rounding:
    // x is on the axis as far as the doubles tell.
    const Eigen::Vector3d radial1 = d - d.dot(t)*t;
    const Eigen::Vector3d radial = radial1 - radial1.dot(t)*t;

    double r;
    Eigen::Vector3d u;
    const bool valid =
        radialDirection(radial, r, u)
     && 2*r >= safeNorm(radial1, radial1.cwiseAbs().maxCoeff());
    if (!valid)
    {
        // Crossing t with the basis vector of its smallest component keeps
        // |t x b| >= sqrt(2/3), so the fallback normal is well conditioned
        int k = 0;
        for (int i = 1; i < 3; ++i)
        {
            if (std::abs(t(i)) < std::abs(t(k)))
            {
                k = i;
            }
        }
        u = t.cross(Eigen::Vector3d::Unit(k)).normalized();
    }
    return onRoundSurface(o, u, r, R, inside, valid);
}

} // End namespace rigid
} // End namespace c4f
