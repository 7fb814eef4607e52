/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "barrierContactMethod.H"
#include "addToRunTimeSelectionTable.H"
#include "barrierLaw.H"
#include "linearizedNormalLaw.H"
#include "PstreamReduceOps.H"

namespace Foam
{
namespace contactMethods
{
    defineTypeNameAndDebug(barrier, 0);
    addContactMethodToTables(barrier);
}
}


// infinite at a closed gap: the bodies start apart, the gap stays open
const Foam::contactMethodTraits
Foam::contactMethods::barrier::typeTraits
{
    contactMethodTraits::answerKind::barrier,
    true,  // openStart
    true,  // allowsSlip
    contactMethodTraits::multiplierKind::none,
    true,  // finiteStrain
    "dhatScale 1e-3; kappaScale 1; stepFraction 0.2; gapFloor 0.01;"
    " extensionScale 1e-4; maxKappaFactor 100; lawTolerance 1e-6;"
};


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::contactMethods::barrier::minGap
(
    const contactSlaveState& state
)
{
    scalar g = GREAT;
    forAll(state.gap, facei)
    {
        if (state.inRange[facei])
        {
            g = min(g, state.gap[facei]);
        }
    }
    return returnReduce(g, minOp<scalar>());
}


void Foam::contactMethods::barrier::checkOpenStart
(
    const contactSlaveState& state
) const
{
    label nClosed = 0;
    scalar worst = GREAT;
    forAll(state.gap, facei)
    {
        if (state.inRange[facei] && !(state.gap[facei] > 0))
        {
            ++nClosed;
            worst = min(worst, state.gap[facei]);
        }
    }
    reduce(nClosed, sumOp<label>());
    reduce(worst, minOp<scalar>());
    if (nClosed)
    {
        const label nInRange =
            returnReduce
            (
                label(std::count(state.inRange.begin(), state.inRange.end(), true)),
                sumOp<label>()
            );
        FatalIOErrorInFunction(coeffs_)
            << "The barrier method needs an open start, but contact"
            << " patch " << patch_.name() << " (" << coeffs_.name()
            << ") touches or penetrates its master: " << nClosed
            << " of its " << nInRange << " faces in range have"
            << " g_N <= 0, the worst g_N = " << worst << " m. Every"
            << " gap must be > 0 (and best below dhat = " << dhat_
            << " m for a smooth first step): open a gap between the"
            << " bodies, e.g. an initial displacement of one body"
            << " (the tutorials' Allrun -gap)" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactMethods::barrier::barrier
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    contactMethod(patch, coeffs),
    dhat_(coeffs.getOrDefault<scalar>("dhat", -1)),
    dhatScale_(coeffs.get<scalar>("dhatScale")),
    kappaScale_(coeffs.get<scalar>("kappaScale")),
    stepFraction_(coeffs.get<scalar>("stepFraction")),
    gapFloor_(coeffs.get<scalar>("gapFloor")),
    extensionScale_(coeffs.get<scalar>("extensionScale")),
    maxKappaFactor_(coeffs.get<scalar>("maxKappaFactor")),
    lawTolerance_(coeffs.get<scalar>("lawTolerance")),
    started_(false),
    newStep_(true),
    previousMinGap_(GREAT),
    nUpdates_(0)
{
    const auto invalid = [&]
    (
        const char* name,
        const scalar v,
        const std::string& valid
    )
    {
        FatalIOErrorInFunction(coeffs)
            << "Invalid " << name << " " << v << " in " << coeffs.name()
            << " (contact patch " << patch.name() << "): it must be "
            << valid.c_str() << exit(FatalIOError);
    };

    if (coeffs.found("dhat") && !c4f::contact::validBarrierLength(dhat_))
    {
        invalid
        (
            "dhat", dhat_,
            c4f::contact::describeBarrierLengthRequirement()
          + "; leave it out for dhatScale (default 1e-3) of the largest"
            " slave cell size"
        );
    }
    if (!c4f::contact::validBarrierFraction(dhatScale_))
    {
        invalid
        (
            "dhatScale", dhatScale_,
            c4f::contact::describeBarrierFractionRequirement()
          + " (dhat as a fraction of the largest slave cell size)"
        );
    }
    if (!c4f::contact::validBarrierScale(kappaScale_))
    {
        invalid
        (
            "kappaScale", kappaScale_,
            c4f::contact::describeBarrierScaleRequirement()
          + " (kappa = kappaScale K/h)"
        );
    }
    if (!c4f::contact::validBarrierFraction(stepFraction_))
    {
        invalid
        (
            "stepFraction", stepFraction_,
            c4f::contact::describeBarrierFractionRequirement()
          + " (every gap keeps at least this fraction of its value over an"
            " update; 0.1 to 0.2 is usual)"
        );
    }
    if (!c4f::contact::validBarrierFraction(gapFloor_))
    {
        invalid
        (
            "gapFloor", gapFloor_,
            c4f::contact::describeBarrierFractionRequirement()
          + " (of dhat)"
        );
    }
    if
    (
        !c4f::contact::validBarrierFraction(extensionScale_)
     || !(extensionScale_ < gapFloor_)
    )
    {
        invalid
        (
            "extensionScale", extensionScale_,
            c4f::contact::describeBarrierFractionRequirement()
          + " (of dhat) and below gapFloor (" + std::to_string(gapFloor_)
          + "), which the answer's gaps lie above; 1e-4 is usual"
        );
    }
    if (!c4f::contact::validBarrierFraction(lawTolerance_))
    {
        invalid
        (
            "lawTolerance", lawTolerance_,
            c4f::contact::describeBarrierFractionRequirement()
          + " (of the largest pressure; 1e-6 is usual)"
        );
    }
    if (!(maxKappaFactor_ >= 1 && std::isfinite(maxKappaFactor_)))
    {
        invalid
        (
            "maxKappaFactor", maxKappaFactor_,
            "a finite number >= 1 (1: kappa never changes)"
        );
    }

    // 0 until the first corrector sets it from K/h
    state_.add("barrierStiffness", 0, dimPressure/dimLength);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::contactMethods::barrier::contactRange
(
    const contactSlaveState& state
)
{
    if (dhat_ < 0)
    {
        // Taken with every processor's faces, so that a decomposed run
        // takes the serial run's value
        dhat_ =
            dhatScale_
           *returnReduce(state.h.size() ? max(state.h) : 0, maxOp<scalar>());
    }
    return dhat_;
}


void Foam::contactMethods::barrier::beginStep()
{
    newStep_ = true;
    nUpdates_ = 0;
}


void Foam::contactMethods::barrier::correct
(
    const contactSlaveState& state,
    contactSlaveCondition& cond
)
{
    cond.nChanged = 0;

    // dhat, taken once with every processor's faces (contactRange)
    contactRange(state);

    scalarField& k = kappa();
    bool initialised = false;
    forAll(k, facei)
    {
        if (!(k[facei] > 0))
        {
            k[facei] = c4f::contact::barrierInitialStiffness
            (
                kappaScale_, state.K[facei], state.h[facei]
            );
            initialised = true;
        }
    }

    // Every gap in range must be open at the start (an input error). Later
    // an iterate may cross g = 0: the law's extension pushes it back, and
    // a converged state below the extension is not taken (updateMultipliers)
    if (!started_)
    {
        checkOpenStart(state);
    }

    const scalar minG = minGap(state);
    if (newStep_)
    {
        previousMinGap_ = minG;
        newStep_ = false;
    }
    if (!started_ || initialised)
    {
        Info<< "    contact " << patch_.name() << ": barrier dhat = " << dhat_
            << " m, kappa = " << gMin(k) << " .. " << gMax(k)
            << " Pa/m (kappaScale " << kappaScale_ << " K/h), min gap = "
            << minG << " m" << endl;
    }
    started_ = true;

    forAll(state.gap, facei)
    {
        const scalar g = state.gap[facei];

        cond.pressure[facei] = carriedPressure(state, cond, facei);
        cond.clearLaw(facei);

        const bool active = state.inRange[facei] && g < dhat_;
        if (active)
        {
            // The Newton step: the law's tangent at the current gap, or,
            // for a face far closer than its reaction asks, at the gap
            // its reaction gives
            const scalar gStar =
                c4f::contact::barrierLinearisationGap
                (
                    g, state.reaction[facei], dhat_, k[facei]
                );
            const c4f::contact::LinearizedNormalLaw lin =
                c4f::contact::linearizeNormalLaw
                (
                    c4f::contact::barrierPressureExtended
                    (
                        gStar, dhat_, k[facei], extensionGap()
                    ),
                    gStar
                );
            cond.coupled[facei] = lin.coupled;
            cond.compliance[facei] = lin.compliance;
            cond.explicitPressure[facei] = lin.pressure0;
        }

        cond.setActive(facei, active);
    }
}


bool Foam::contactMethods::barrier::updateMultipliers
(
    const contactSlaveState& state,
    const contactSlaveCondition&
)
{
    const scalar minG = minGap(state);

    scalarField& k = kappa();
    bool belowCap = false;
    forAll(k, facei)
    {
        const scalar kMax =
            maxKappaFactor_
           *c4f::contact::barrierInitialStiffness
            (
                kappaScale_, state.K[facei], state.h[facei]
            );
        belowCap = belowCap || k[facei] < kMax*(1 - 1e-12);
    }
    reduce(belowCap, orOp<bool>());

    // A state on the law's extension is not the barrier's answer: the
    // barrier, stiffer, must hold the faces further apart
    const bool onExtension = minG < extensionGap();
    if (onExtension && !belowCap)
    {
        FatalIOErrorInFunction(coeffs_)
            << "Contact patch " << patch_.name() << " (" << coeffs_.name()
            << "): the converged state has a gap of " << minG << " m,"
            << " below the barrier's extension (extensionScale "
            << extensionScale_ << " of dhat = " << dhat_ << " m), with kappa"
            << " at maxKappaFactor " << maxKappaFactor_ << " times its"
            << " initial value: the barrier cannot carry the load there."
            << " Raise maxKappaFactor or kappaScale (or dhat)"
            << exit(FatalIOError);
    }
    const bool increase =
        belowCap
     && (
            onExtension
         || c4f::contact::barrierStiffnessShouldIncrease
            (
                previousMinGap_, minG, gapFloor_*dhat_
            )
        );

    Info<< "    contact " << patch_.name() << ": barrier stiffness update "
        << nUpdates_ << "  min gap/dhat = " << minG/dhat_
        << "  previous " << previousMinGap_/dhat_
        << "  floor " << gapFloor_;

    previousMinGap_ = minG;

    if (!increase)
    {
        Info<< "  converged" << endl;
        return false;
    }

    forAll(k, facei)
    {
        const scalar kMax =
            maxKappaFactor_
           *c4f::contact::barrierInitialStiffness
            (
                kappaScale_, state.K[facei], state.h[facei]
            );
        k[facei] = min(2*k[facei], kMax);
    }
    ++nUpdates_;

    Info<< "  kappa doubled to " << gMax(k) << " Pa/m" << endl;
    return true;
}


bool Foam::contactMethods::barrier::lawConverged
(
    const contactSlaveState& state,
    const scalarField& pressure
) const
{
    const scalarField& k = state_["barrierStiffness"];
    scalar worst = 0;
    scalar pMax = 0;
    forAll(state.gap, facei)
    {
        if (state.inRange[facei] && state.gap[facei] < dhat_)
        {
            const scalar p =
                c4f::contact::barrierPressureExtended
                (
                    state.gap[facei], dhat_, k[facei], extensionGap()
                ).pressure;
            worst = max(worst, mag(p - pressure[facei]));
            pMax = max(pMax, mag(pressure[facei]));
        }
    }
    reduce(worst, maxOp<scalar>());
    reduce(pMax, maxOp<scalar>());
    return worst <= lawTolerance_*pMax;
}


Foam::scalar Foam::contactMethods::barrier::stepLimit
(
    const contactSlaveState& before,
    const scalarField& gapAfter,
    const boolList& inRangeAfter,
    const bool newtonStep
) const
{
    // An update is limited when a gap would fall below half its fraction;
    // then it is scaled so that the closest face keeps the whole fraction:
    // the margin takes the round-off of the measured gaps (differences of
    // coordinates), so that a scaled update is not limited again
    bool limited = false;
    scalar alpha = 1;
    forAll(gapAfter, facei)
    {
        if (!inRangeAfter[facei])
        {
            continue;
        }
        if (before.inRange[facei] && before.gap[facei] < dhat_ && !newtonStep)
        {
            // Coupled by the law's tangent in the corrector's solve: the
            // extension takes a gap the solve misjudged (limiting the
            // whole update for it stalled every face, docs/methods.md)
            continue;
        }
        if (before.inRange[facei])
        {
            const scalar g = before.gap[facei];
            limited = limited || gapAfter[facei] < 0.5*stepFraction_*g;
            alpha = min
            (
                alpha,
                c4f::contact::barrierStepLimit(g, gapAfter[facei], stepFraction_)
            );
        }
        else if (!(gapAfter[facei] > 0))
        {
            // A face that came into range closed: no gap before to keep a
            // fraction of; halve the update and measure again
            limited = true;
            alpha = min(alpha, scalar(0.5));
        }
    }
    return limited ? alpha : 1;
}
