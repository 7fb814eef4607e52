/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "planeRigidSurface.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace rigidSurfaces
{
    defineTypeNameAndDebug(plane, 0);
    addToRunTimeSelectionTable(rigidSurface, plane, dictionary);
}
}


Foam::rigidSurfaces::plane::plane
(
    const dictionary& dict,
    const objectRegistry&
)
:
    rigidSurface(dict),
    point_(dict.get<vector>("point")),
    normal_(readDirection("normal"))
{}


c4f::rigid::SurfacePoint Foam::rigidSurfaces::plane::closestReference
(
    const Eigen::Vector3d& X,
    const Eigen::Vector3d&,
    const scalar
) const
{
    return c4f::rigid::closestOnPlane(X, c4fConvert::toEigen(point_), c4fConvert::toEigen(normal_));
}


void Foam::rigidSurfaces::plane::tessellate
(
    const Foam::point& centre,
    const scalar extent,
    pointField& points,
    faceList& faces
) const
{
    // A square of half size extent about the centre's foot on the plane
    const vector c = centre - normal_*((centre - point_) & normal_);
    vector t1, t2;
    tangentBasis(normal_, t1, t2);
    points.setSize(4);
    points[0] = c - extent*t1 - extent*t2;
    points[1] = c + extent*t1 - extent*t2;
    points[2] = c + extent*t1 + extent*t2;
    points[3] = c - extent*t1 + extent*t2;
    faces.setSize(1);
    faces[0] = face(identity(4));
}


// ************************************************************************* //
