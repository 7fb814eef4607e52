/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "uzawaMethod.H"
#include "normalContactLaws.H"
#include "augmentedLagrangeLaw.H"
#include "PstreamReduceOps.H"

#include <cmath>

Foam::contactMethods::uzawaMethod::uzawaMethod
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    uzawaMethod(patch, coeffs, "penetrationTolerance", "<-g>")
{}


Foam::contactMethods::uzawaMethod::uzawaMethod
(
    const fvPatch& patch,
    const dictionary& coeffs,
    const word& constraintTolName,
    const string& measureName
)
:
    contactMethod(patch, coeffs),
    scale_(coeffs.get<scalar>("penaltyScale")),
    measureName_(measureName),
    constraintTol_(coeffs.get<scalar>(constraintTolName)),
    multiplierTol_(coeffs.get<scalar>("multiplierTolerance")),
    maxUpdates_(coeffs.get<label>("maxUpdates")),
    nUpdates_(0),
    converged_(true),
    everyCorrector_(coeffs.get<word>("multiplierUpdate") == "corrector")
{
    const word update(coeffs.get<word>("multiplierUpdate"));
    if (!everyCorrector_ && update != "converged")
    {
        FatalIOErrorInFunction(coeffs)
            << "Invalid multiplierUpdate " << update << " in "
            << coeffs.name() << " (contact patch " << patch.name()
            << "): valid are corrector (in every outer corrector, part of"
            << " the accelerated iterate) and converged (once the"
            << " correctors have converged)" << exit(FatalIOError);
    }

    if (!c4f::contact::validPenalty(scale_))
    {
        FatalIOErrorInFunction(coeffs)
            << "Invalid penaltyScale " << scale_ << " in " << coeffs.name()
            << " (contact patch " << patch.name() << "): "
            << c4f::contact::describePenaltyRequirement().c_str()
            << exit(FatalIOError);
    }

    const auto positive = [&](const char* name, const scalar v)
    {
        if (!(v > 0 && std::isfinite(v)))
        {
            FatalIOErrorInFunction(coeffs)
                << "Invalid " << name << " " << v << " in " << coeffs.name()
                << " (contact patch " << patch.name() << "): it must be"
                << " positive and finite" << exit(FatalIOError);
        }
    };
    positive(constraintTolName.c_str(), constraintTol_);
    positive("multiplierTolerance", multiplierTol_);

    if (maxUpdates_ < 1)
    {
        FatalIOErrorInFunction(coeffs)
            << "Invalid maxUpdates " << maxUpdates_ << " in "
            << coeffs.name() << " (contact patch " << patch.name()
            << "): it must be at least 1" << exit(FatalIOError);
    }

    state_.add("contactMultiplier", 0, dimPressure);
}


Foam::scalar Foam::contactMethods::uzawaMethod::constraintViolation
(
    const contactSlaveState& state,
    const label facei,
    const scalar
) const
{
    return max(-state.constraintGap[facei], scalar(0));
}


void Foam::contactMethods::uzawaMethod::beginStep()
{
    nUpdates_ = 0;
    converged_ = true;
}


Foam::tmp<Foam::scalarField>
Foam::contactMethods::uzawaMethod::newMultipliers
(
    const contactSlaveState& state,
    const contactSlaveCondition& cond
) const
{
    tmp<scalarField> tlam(new scalarField(lambda().size(), 0));
    scalarField& lam = tlam.ref();
    forAll(lam, facei)
    {
        if (state.inRange[facei])
        {
            lam[facei] = max(scalar(0), newMultiplier(state, cond, facei));
        }
    }
    return tlam;
}


void Foam::contactMethods::uzawaMethod::updateCorrectorMultipliers
(
    const contactSlaveState& state,
    const contactSlaveCondition& cond
)
{
    if (everyCorrector_)
    {
        lambda() = newMultipliers(state, cond);
    }
}


bool Foam::contactMethods::uzawaMethod::updateMultipliers
(
    const contactSlaveState& state,
    const contactSlaveCondition& cond
)
{
    scalarField& lam = lambda();
    const scalarField lamNew(newMultipliers(state, cond));

    scalar maxViolation = 0;
    scalar dLambda = 0;
    scalar lambdaMax = 0;
    forAll(lam, facei)
    {
        if (state.inRange[facei])
        {
            maxViolation = max
            (
                maxViolation,
                constraintViolation(state, facei, lamNew[facei])/state.h[facei]
            );
        }
        dLambda = max(dLambda, mag(lamNew[facei] - lam[facei]));
        lambdaMax = max(lambdaMax, mag(lamNew[facei]));
    }

    // One decision on every processor
    reduce(maxViolation, maxOp<scalar>());
    reduce(dLambda, maxOp<scalar>());
    reduce(lambdaMax, maxOp<scalar>());

    converged_ = c4f::contact::uzawaConverged
    (
        maxViolation, 1, constraintTol_, dLambda, lambdaMax, multiplierTol_
    );

    // The relative change as printed: where every new multiplier is zero
    // (the contact opened) a change divided by max(lambdaMax, VSMALL)
    // overflowed (a floating point exception of augmentedLagrange after a
    // lift-off, hertzCylinder -unload); GREAT stands for it there
    const scalar relChange =
        dLambda <= 0 ? 0
      : dLambda < GREAT*lambdaMax ? dLambda/lambdaMax
      : GREAT;

    Info<< "    contact " << patch_.name() << ": multiplier update "
        << nUpdates_ << "  max " << measureName_.c_str() << "/h = "
        << maxViolation
        << "  max|dlambda|/max|lambda| = " << relChange
        << (converged_ ? "  converged" : "") << endl;

    if (converged_ || nUpdates_ >= maxUpdates_)
    {
        return false;
    }

    lam = lamNew;
    ++nUpdates_;
    return true;
}
