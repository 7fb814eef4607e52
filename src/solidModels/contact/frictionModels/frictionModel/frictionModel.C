/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "frictionModel.H"

namespace Foam
{
    defineTypeNameAndDebug(frictionModel, 0);
    defineRunTimeSelectionTable(frictionModel, dictionary);
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::frictionModel::addHistory()
{
    state_.add("contactStickPoint", vector::zero, dimLength);
    state_.add("contactSlip", vector::zero, dimLength);
    state_.add("contactStick", -1, dimless);
}


void Foam::frictionModel::setStick
(
    const label facei,
    const scalar flag,
    contactSlaveCondition& cond
)
{
    scalarField& stick = state_["contactStick"];
    if (stick[facei] != flag)
    {
        ++cond.nChanged;
    }
    stick[facei] = flag;
}


Foam::vector Foam::frictionModel::tangentialGap
(
    const contactSlaveState& state,
    const contactSlaveCondition& cond,
    const label facei
) const
{
    const vector& n = state.normal[facei];
    return tangential
    (
        n,
        state.relative[facei]
      - state_.field<vector>("contactStickPoint")[facei]
      + cond.tangentialCompliance[facei]
       *(tangential(n, state.traction[facei]) - lambdaT(cond, facei))
    );
}


Foam::vector Foam::frictionModel::lambdaT
(
    const contactSlaveCondition& cond,
    const label facei
) const
{
    vector lambda(cond.tangentialPressure0[facei]);
    if (augmented())
    {
        lambda += state_.field<vector>("contactTangentialMultiplier")[facei];
    }
    return lambda;
}


void Foam::frictionModel::releaseAll(contactSlaveCondition& cond)
{
    cond.tied = false;
    cond.tangentialTraction = Zero;
    cond.tangentialMultiplier = Zero;
}


void Foam::frictionModel::tie
(
    const label facei,
    contactSlaveCondition& cond
) const
{
    cond.tied[facei] = true;
    cond.tangentialMultiplier[facei] = lambdaT(cond, facei);
}


void Foam::frictionModel::updateSlip
(
    const contactSlaveState& state,
    const contactSlaveCondition& cond,
    const label facei
)
{
    vectorField& slip = state_.field<vector>("contactSlip");

    slip[facei] = slipAtStepStart_[facei];
    if (state_["contactStick"][facei] == 0)
    {
        slip[facei] += tangentialGap(state, cond, facei);
    }
}


void Foam::frictionModel::noteReleases(const contactSlaveCondition& cond)
{
    if
    (
        !tieClosing_
     && wasCoupled_.size() == cond.coupled.size()
     && releases_.size() == cond.coupled.size()
    )
    {
        forAll(wasCoupled_, facei)
        {
            if (wasCoupled_[facei] && !cond.coupled[facei])
            {
                if (++releases_[facei] > 1)
                {
                    closedAtStart_[facei] = false;
                }
            }
        }
    }
    wasCoupled_ = cond.coupled;
}


void Foam::frictionModel::freeClosing
(
    const label facei,
    contactSlaveCondition& cond
)
{
    setStick(facei, 0, cond);
    state_.field<vector>("contactSlip")[facei] = slipAtStepStart_[facei];
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::frictionModel::frictionModel
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    patch_(patch),
    coeffs_(coeffs),
    state_(patch.size()),
    slipAtStepStart_(patch.size(), Zero),
    closedAtStart_(),
    wasCoupled_(),
    releases_(),
    tieClosing_(false),
    multipliersConverged_(true)
{
    const word closing(coeffs.getOrDefault<word>("closing", "free"));
    if (closing != "free" && closing != "tied")
    {
        FatalIOErrorInFunction(coeffs)
            << "Invalid closing " << closing << " in " << coeffs.name()
            << " (contact patch " << patch.name() << "): valid are free"
            << " (a face that closes within a load step carries no friction"
            << " in it) and tied (it is treated as closed at the step's"
            << " start)" << exit(FatalIOError);
    }
    tieClosing_ = (closing == "tied");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::frictionModel::beginStep
(
    const contactSlaveState& state,
    const contactSlaveCondition& cond,
    const scalar contactRange
)
{
    if (!hasTangentialLaw())
    {
        return;
    }

    const scalarField& stick = state_["contactStick"];
    vectorField& R = state_.field<vector>("contactStickPoint");

    // contactSlip already holds the last step's slip (updateSlip, at its
    // last corrector); the stick point of a slipping face moves by it
    multipliersConverged_ = true;
    slipAtStepStart_ = state_.field<vector>("contactSlip");
    closedAtStart_.setSize(stick.size());
    releases_ = labelList(stick.size(), 0);
    wasCoupled_ = cond.coupled;
    forAll(stick, facei)
    {
        closedAtStart_[facei] =
            tieClosing_
         || stick[facei] >= 0
         || state.gap[facei]
         <= max(touchTolerance_*state.h[facei], contactRange);

        if (stick[facei] < 0)
        {
            R[facei] = state.relative[facei];
        }
        else if (stick[facei] == 0)
        {
            R[facei] += tangentialGap(state, cond, facei);
        }
    }
}


void Foam::frictionModel::augmentMultipliers()
{
    if (hasTangentialLaw())
    {
        state_.add("contactTangentialMultiplier", vector::zero, dimPressure);
    }
}


bool Foam::frictionModel::updateMultipliers
(
    const contactSlaveState& state,
    const contactSlaveCondition& cond,
    const scalar tolerance
)
{
    if (!augmented())
    {
        return false;
    }

    vectorField& lambda = state_.field<vector>("contactTangentialMultiplier");
    scalar dLambda = 0;
    scalar lambdaMax = 0;
    forAll(lambda, facei)
    {
        const vector lambdaNew
        (
            cond.coupled[facei]
          ? tangential(state.normal[facei], state.traction[facei])
          : vector::zero
        );
        dLambda = max(dLambda, mag(lambdaNew - lambda[facei]));
        lambdaMax = max(lambdaMax, mag(lambdaNew));
        lambda[facei] = lambdaNew;
    }
    reduce(dLambda, maxOp<scalar>());
    reduce(lambdaMax, maxOp<scalar>());

    multipliersConverged_ = dLambda <= tolerance*lambdaMax;

    Info<< "    contact " << patch_.name() << ": tangential multiplier"
        << " update  max|dlambda_T|/max|lambda_T| = "
        << (lambdaMax > 0 ? dLambda/lambdaMax : 0)
        << (multipliersConverged_ ? "  converged" : "") << endl;

    return !multipliersConverged_;
}


void Foam::frictionModel::write(Ostream& os) const
{
    if (coeffs_.size())
    {
        coeffs_.writeEntry(word(frictionName() + "Coeffs"), os);
    }
}


// ************************************************************************* //
