/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "cylinderRigidSurface.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace rigidSurfaces
{
    defineTypeNameAndDebug(cylinder, 0);
    addToRunTimeSelectionTable(rigidSurface, cylinder, dictionary);
}
}


Foam::rigidSurfaces::cylinder::cylinder
(
    const dictionary& dict,
    const objectRegistry&
)
:
    rigidSurface(dict),
    point_(dict.get<vector>("point")),
    axis_(readDirection("axis")),
    radius_(readPositive("radius")),
    inside_(dict.getOrDefault<bool>("inside", false))
{}


c4f::rigid::SurfacePoint Foam::rigidSurfaces::cylinder::closestReference
(
    const Eigen::Vector3d& X,
    const Eigen::Vector3d&,
    const scalar
) const
{
    return c4f::rigid::closestOnCylinder
    (
        X, c4fConvert::toEigen(point_), c4fConvert::toEigen(axis_), radius_, inside_
    );
}


void Foam::rigidSurfaces::cylinder::tessellate
(
    const Foam::point& centre,
    const scalar extent,
    pointField& points,
    faceList& faces
) const
{
    // 96 quads around, over the axis length 2 extent about the centre
    const label n = 96;
    const scalar pi = constant::mathematical::pi;
    const point c = point_ + axis_*((centre - point_) & axis_);
    vector t1, t2;
    tangentBasis(axis_, t1, t2);
    points.setSize(2*n);
    for (label j = 0; j < n; ++j)
    {
        const scalar phi = 2*pi*j/n;
        const vector r = radius_*(cos(phi)*t1 + sin(phi)*t2);
        points[j] = c - extent*axis_ + r;
        points[n + j] = c + extent*axis_ + r;
    }
    faces.setSize(n);
    for (label j = 0; j < n; ++j)
    {
        face f(4);
        f[0] = j;
        f[1] = (j + 1) % n;
        f[2] = n + (j + 1) % n;
        f[3] = n + j;
        faces[j] = f;
    }
}


// ************************************************************************* //
