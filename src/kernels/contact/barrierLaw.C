/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "barrierLaw.H"

#include <cfloat>
#include <cmath>

namespace c4f
{
namespace contact
{

namespace
{

// An overflowed magnitude saturates at the largest double
double saturate(const double v)
{
    return std::isinf(v) ? std::copysign(DBL_MAX, v) : v;
}

} // End anonymous namespace


BarrierValue barrier(const double d, const double dhat)
{
    if (!(d > 0))
    {
        return {DBL_MAX, -DBL_MAX, DBL_MAX};
    }
    if (!(d < dhat))
    {
        return {0.0, 0.0, 0.0};
    }

    // x = d/dhat in (0, 1), u = 1 - x formed from the difference, so that
    // it keeps its digits near dhat; ln x = log1p(-u)
    const double x = d/dhat;
    const double u = (dhat - d)/dhat;
    const double lnx = x < 0.5 ? std::log(x) : std::log1p(-u);

    const double b = saturate(-dhat*dhat*u*u*lnx);
    const double db = saturate(dhat*u*(2*lnx - u/x));
    const double d2b = saturate(u*(3*x + 1)/(x*x) - 2*lnx);
    return {b, db, d2b};
}


NormalLawValue barrierPressure
(
    const double gap,
    const double dhat,
    const double kappa
)
{
    const BarrierValue v = barrier(gap, dhat);
    return {saturate(-kappa*v.db), saturate(-kappa*v.d2b)};
}


NormalLawValue barrierPressureExtended
(
    const double gap,
    const double dhat,
    const double kappa,
    const double extensionGap
)
{
    // A NaN gap takes the barrier's own answer (saturated, never NaN)
    if (std::isnan(gap) || gap >= extensionGap)
    {
        return barrierPressure(gap, dhat, kappa);
    }
    const NormalLawValue e = barrierPressure(extensionGap, dhat, kappa);
    return
    {
        saturate(e.pressure + e.dPressureDGap*(gap - extensionGap)),
        e.dPressureDGap
    };
}


double barrierGapForPressure
(
    const double pressure,
    const double dhat,
    const double kappa
)
{
    // isgreater: a quiet comparison, NaN raises no invalid-operation flag
    if (!std::isgreater(pressure, 0.0))
    {
        return dhat;
    }

    // In t = ln(g/dhat) in (lo, 0): p(t) falls from +inf to 0, so that
    // f(t) = p(t) - pressure changes sign once. lo: 1e-100 dhat, far below
    // any gap a mesh resolves, and where kappa/x^2 stays a double (deeper,
    // the law's overflow traps where floating-point exceptions are on); a
    // pressure beyond p there takes that gap
    double lo = std::log(1e-100);
    double hi = 0.0;
    if (barrierPressure(dhat*std::exp(lo), dhat, kappa).pressure < pressure)
    {
        return dhat*std::exp(lo);
    }

    // A start near the root (Newton in t creeps, a unit a step, from far
    // off): p ~ kappa dhat^2/g for g << dhat, p ~ 3 kappa dhat u^2 near
    // dhat (u = 1 - g/dhat, see the header); the smaller gap of the two
    double t = 0.5*lo;
    // (as a difference of logarithms: kappa dhat/p overflows for a
    // denormal p, which a trap on overflow stops)
    const double far = std::log(kappa) + std::log(dhat) - std::log(pressure);
    const double u = std::sqrt(pressure/(3*kappa*dhat));
    const double near = u < 1 ? std::log1p(-u) : far;
    const double guess = far < near ? far : near;
    if (guess > lo && guess < hi)
    {
        t = guess;
    }
    for (int iter = 0; iter < 200; ++iter)
    {
        const double g = dhat*std::exp(t);
        const NormalLawValue v = barrierPressure(g, dhat, kappa);
        const double f = v.pressure - pressure;
        if (f > 0)
        {
            lo = t;
        }
        else
        {
            hi = t;
        }
        // df/dt = dp/dg g; where p saturates (DBL_MAX) the step means
        // nothing: bisect
        const double slope = v.dPressureDGap*g;
        double next = 0.5*(lo + hi);
        if (v.pressure < DBL_MAX && slope < 0 && std::isfinite(slope))
        {
            const double newton = t - f/slope;
            if (newton > lo && newton < hi)
            {
                next = newton;
                if (std::abs(next - t) <= 1e-15)
                {
                    return dhat*std::exp(next);
                }
            }
        }
        if (hi - lo <= 1e-15)
        {
            return dhat*std::exp(next);
        }
        t = next;
    }
    return dhat*std::exp(t);
}


double barrierLinearisationGap
(
    const double gap,
    const double reaction,
    const double dhat,
    const double kappa
)
{
    if (!std::isgreater(reaction, 0.0) || !std::isgreater(gap, 0.0))
    {
        return gap;
    }
    // G(p_r) > 10 g  <=>  p_r < p(10 g), p strictly decreasing on (0, dhat)
    // and 0 beyond: one evaluation of the law for most faces, the
    // inverse only for those it rescues
    if (!(reaction < barrierPressure(10*gap, dhat, kappa).pressure))
    {
        return gap;
    }
    const double gR = barrierGapForPressure(reaction, dhat, kappa);
    return std::max(gap, std::min(gR, 0.5*dhat));
}


double barrierInitialStiffness
(
    const double scale,
    const double K,
    const double h
)
{
    return stiffnessScaledPenalty(scale, K, h);
}


double barrierStepLimit
(
    const double gapBefore,
    const double gapAfter,
    const double fraction
)
{
    // Written so that a NaN gap falls through to 1
    if (!(gapBefore > 0) || !(gapAfter < fraction*gapBefore))
    {
        return 1.0;
    }
    // gapAfter < fraction gapBefore < gapBefore: the denominator is
    // positive, and alpha in (0, 1)
    const double alpha = (1 - fraction)*gapBefore/(gapBefore - gapAfter);
    return alpha < 1 ? alpha : 1.0;
}


bool barrierStiffnessShouldIncrease
(
    const double previousMinGap,
    const double minGap,
    const double floorGap
)
{
    return minGap < floorGap && minGap < previousMinGap;
}


bool validBarrierLength(const double dhat)
{
    return dhat > 0 && std::isfinite(dhat);
}


bool validBarrierScale(const double scale)
{
    return scale > 0 && std::isfinite(scale);
}


bool validBarrierFraction(const double f)
{
    return f > 0 && f < 1;
}


std::string describeBarrierLengthRequirement()
{
    return
        "a positive, finite length [m], much smaller than the cell size"
        " (about 1e-3 h)";
}


std::string describeBarrierScaleRequirement()
{
    return "a positive, finite number";
}


std::string describeBarrierFractionRequirement()
{
    return "a fraction strictly between 0 and 1";
}

} // End namespace contact
} // End namespace c4f
