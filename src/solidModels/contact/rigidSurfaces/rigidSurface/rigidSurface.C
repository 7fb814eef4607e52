/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "rigidSurface.H"

#include <cmath>

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
    centreOfRotation_(Zero),
    forceDirection_(Zero),
    force_(),
    forceTolerance_(1e-6),
    forceState_(),
    nForceUpdates_(0)
{
    if (dict.found("forceControl"))
    {
        if (!dict.isDict("forceControl"))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'forceControl' of " << dict.name() << " must be a"
                << " dictionary (direction, force, tolerance, position)"
                << exit(FatalIOError);
        }
        const dictionary& fc = dict.subDict("forceControl");
        const vector e = fc.get<vector>("direction");
        if (!(mag(e) > VSMALL) || !std::isfinite(mag(e)))
        {
            FatalIOErrorInFunction(fc)
                << "Entry 'direction' of " << fc.name() << " is " << e
                << "; the force-controlled direction must be a non-zero"
                << " vector (the way the tool pushes into the body)"
                << exit(FatalIOError);
        }
        forceDirection_ = e/mag(e);
        force_ = Function1<scalar>::New("force", fc);
        forceTolerance_ = fc.getOrDefault<scalar>("tolerance", 1e-6);
        if (!(forceTolerance_ > 0 && forceTolerance_ < 1))
        {
            FatalIOErrorInFunction(fc)
                << "Entry 'tolerance' of " << fc.name() << " is "
                << forceTolerance_ << "; valid: 0 < tolerance < 1 (relative"
                << " to the prescribed force)" << exit(FatalIOError);
        }
        forceState_.s = fc.getOrDefault<scalar>("position", 0);
        // The secant's other point, written with each time, so that a
        // restart moves as the run it continues would
        if (fc.found("previousPosition") && fc.found("previousForce"))
        {
            forceState_.sPrev = fc.get<scalar>("previousPosition");
            forceState_.PPrev = fc.get<scalar>("previousForce");
            forceState_.havePrev = true;
        }
    }

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
    if (!(mag(v) > VSMALL) || !std::isfinite(mag(v)))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry '" << key << "' of " << dict_.name() << " is " << v
            << "; a " << dict_.get<word>("type") << " needs a non-zero,"
            << " finite " << key << " vector" << exit(FatalIOError);
    }
    return v/mag(v);
}


void Foam::rigidSurface::tangentBasis
(
    const vector& n,
    vector& t1,
    vector& t2
)
{
    // Against the axis least aligned with n, so that t1 is never short
    t1 = n ^ vector(1, 0, 0);
    if (mag(t1) < 0.5)
    {
        t1 = n ^ vector(0, 1, 0);
    }
    t1 /= mag(t1);
    t2 = n ^ t1;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::rigidSurface::translation(const scalar t) const
{
    const vector u = translation_.valid() ? translation_->value(t) : Zero;
    if (!forceControlled())
    {
        return u;
    }
    const vector& e = forceDirection_;
    return u - e*(e & u) + e*forceState_.s;
}


Foam::scalar Foam::rigidSurface::targetForce(const scalar t) const
{
    return force_.valid() ? force_->value(t) : 0;
}


bool Foam::rigidSurface::updatePosition
(
    const scalar P,
    const scalar t,
    const scalar k0,
    const scalar maxStep
)
{
    c4f::rigid::ForceControlState& st = forceState_;
    const scalar Pt = targetForce(t);

    // Nothing to move by: no contact at the first state of the run, where
    // a load is asked for (a restart's first state has its secant)
    if (!(P > 0) && Pt > 0 && nForceUpdates_ == 0 && !st.havePrev)
    {
        FatalIOErrorInFunction(dict_.subDict("forceControl"))
            << "The force-controlled tool of " << dict_.name() << " carries"
            << " no force at its position " << st.s << " m along "
            << forceDirection_ << " (P = " << P << " N, prescribed " << Pt
            << " N): no slave face touches it, so its position cannot"
            << " follow from the force. Start it pressed into the body"
            << " (forceControl/position, its translation along direction:"
            << " touching is not enough, P must be > 0)"
            << exit(FatalIOError);
    }

    // The converged force at the current s (a new step's first state is
    // at the position the last one ended at: the secant keeps its other
    // point, P(s) being the same curve)
    st.P = P;

    if (c4f::rigid::forceControlConverged(P, Pt, forceTolerance_))
    {
        return false;
    }

    const scalar sNew =
        c4f::rigid::forceControlUpdate(st, Pt, max(k0, VSMALL), maxStep);
    st.sPrev = st.s;
    st.PPrev = st.P;
    st.havePrev = true;
    st.s = sNew;
    ++nForceUpdates_;
    return true;
}


void Foam::rigidSurface::write(Ostream& os) const
{
    dictionary d(dict_);
    if (forceControlled())
    {
        dictionary& fc = d.subDict("forceControl");
        fc.set("position", forceState_.s);
        if (forceState_.havePrev)
        {
            fc.set("previousPosition", forceState_.sPrev);
            fc.set("previousForce", forceState_.PPrev);
        }
    }
    // Full precision: the position's rounding must not cost a restart
    // moves (a relative 5e-6 at the default 6 digits, above the force's
    // tolerance)
    const label prec = os.precision(17);
    os.beginBlock("rigidSurface");
    d.write(os, false);
    os.endBlock();
    os.precision(prec);
}


c4f::rigid::RigidMotion Foam::rigidSurface::motion(const scalar t) const
{
    const vector theta = rotation_.valid() ? rotation_->value(t) : Zero;
    return c4f::rigid::RigidMotion
    (
        c4fConvert::toEigen(translation(t)), c4fConvert::toEigen(theta), c4fConvert::toEigen(centreOfRotation_)
    );
}


c4f::rigid::SurfacePoint Foam::rigidSurface::closest
(
    const point& x,
    const vector& slaveNormal,
    const scalar t,
    const scalar maxDistance
) const
{
    const c4f::rigid::RigidMotion m(motion(t));
    c4f::rigid::SurfacePoint sp =
        closestReference
        (
            m.applyInverse(c4fConvert::toEigen(x)),
            m.rotation().transpose()*c4fConvert::toEigen(slaveNormal),
            maxDistance
        );
    sp.point = m.apply(sp.point);
    sp.normal = m.rotateVector(sp.normal);
    return sp;
}


// ************************************************************************* //
