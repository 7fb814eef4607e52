/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "rigidSurface.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(rigidSurface, 0);
    defineRunTimeSelectionTable(rigidSurface, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rigidSurface::rigidSurface(const dictionary& dict)
:
    dict_(dict),
    translation_(),
    rotation_(),
    centreOfRotation_(Zero)
{
    const dictionary* motionPtr = dict.findDict("motion");
    if (motionPtr)
    {
        const dictionary& m = *motionPtr;
        if (m.found("translation"))
        {
            translation_ = Function1<vector>::New("translation", m);
        }
        if (m.found("rotation"))
        {
            rotation_ = Function1<vector>::New("rotation", m);
        }
        centreOfRotation_ =
            m.getOrDefault<vector>("centreOfRotation", Zero);
    }
    else if (dict.found("motion"))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'motion' of " << dict.name() << " must be a dictionary"
            << " (translation, rotation, centreOfRotation)"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::rigidSurface::readPositive(const word& key) const
{
    const scalar v = dict_.get<scalar>(key);
    if (!(v > 0))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry '" << key << "' of " << dict_.name() << " is " << v
            << "; a " << dict_.get<word>("type") << " needs a positive "
            << key << exit(FatalIOError);
    }
    return v;
}


Foam::vector Foam::rigidSurface::readDirection(const word& key) const
{
    const vector v = dict_.get<vector>(key);
    if (!(mag(v) > VSMALL))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry '" << key << "' of " << dict_.name() << " is " << v
            << "; a " << dict_.get<word>("type") << " needs a non-zero "
            << key << " vector" << exit(FatalIOError);
    }
    return v/mag(v);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::rigidSurface::translation(const scalar t) const
{
    return translation_.valid() ? translation_->value(t) : vector::zero;
}


c4f::rigid::RigidMotion Foam::rigidSurface::motion(const scalar t) const
{
    const vector theta = rotation_.valid() ? rotation_->value(t) : Zero;
    return c4f::rigid::RigidMotion
    (
        toEigen(translation(t)), toEigen(theta), toEigen(centreOfRotation_)
    );
}


c4f::rigid::SurfacePoint Foam::rigidSurface::closest
(
    const point& x,
    const scalar t,
    const scalar maxDistance
) const
{
    const c4f::rigid::RigidMotion m(motion(t));
    c4f::rigid::SurfacePoint sp =
        closestReference(m.applyInverse(toEigen(x)), maxDistance);
    sp.point = m.apply(sp.point);
    sp.normal = m.rotateVector(sp.normal);
    return sp;
}


// ************************************************************************* //
