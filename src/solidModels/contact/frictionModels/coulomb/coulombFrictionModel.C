/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "coulombFrictionModel.H"
#include "addToRunTimeSelectionTable.H"
#include "coulombReturnMap.H"
#include "eigenFoamConversions.H"

namespace Foam
{
namespace frictionModels
{
    defineTypeNameAndDebug(coulomb, 0);
    addToRunTimeSelectionTable(frictionModel, coulomb, dictionary);
}
}


namespace
{
    Foam::scalar readMu(const Foam::dictionary& coeffs, const Foam::fvPatch& p)
    {
        using namespace Foam;
        if (!coeffs.found("mu"))
        {
            FatalIOErrorInFunction(coeffs)
                << "Missing entry 'mu' in " << coeffs.name()
                << " (contact patch " << p.name() << "): the friction model"
                << " coulomb needs its coefficient, e.g. coulombCoeffs"
                << " { mu 0.3; }" << exit(FatalIOError);
        }
        return coeffs.get<scalar>("mu");
    }
}


Foam::frictionModels::coulomb::coulomb
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    frictionModel(patch, coeffs),
    mu_(readMu(coeffs, patch))
{
    const c4f::contact::FrictionCheck check =
        c4f::contact::checkFrictionParameters(mu_, 1);
    if (check != c4f::contact::FrictionCheck::ok)
    {
        FatalIOErrorInFunction(coeffs)
            << "Invalid mu " << mu_ << " in " << coeffs.name()
            << " (contact patch " << patch.name() << "): "
            << c4f::contact::describe(check).c_str() << exit(FatalIOError);
    }
    addHistory();
}


Foam::scalar Foam::frictionModels::coulomb::normalPressure
(
    const contactSlaveState& state,
    const label facei
) const
{
    if (state_["contactStick"][facei] < 0)
    {
        // Open at the last decision: lambda_N = 0, the primal-dual trial
        // is the penetration's, c (-g_N)
        return max(-state.pairStiffness[facei]*state.constraintGap[facei], 0);
    }
    return state.reaction[facei];
}


void Foam::frictionModels::coulomb::correct
(
    const contactSlaveState& state,
    contactSlaveCondition& cond
)
{
    releaseAll(cond);
    forAll(cond.tied, facei)
    {
        if (!cond.coupled[facei])
        {
            setStick(facei, -1, cond);
            updateSlip(state, cond, facei);
            continue;
        }
        if (closing(facei, cond))
        {
            freeClosing(facei, cond);
            continue;
        }

        const vector& n = state.normal[facei];
        const c4f::contact::CoulombResult r = c4f::contact::coulombReturnMap
        (
            c4fConvert::toEigen(n),
            c4fConvert::toEigen(tangential(n, state.traction[facei])),
            c4fConvert::toEigen(tangentialGap(state, cond, facei)),
            normalPressure(state, facei),
            mu_,
            state.pairStiffness[facei]
        );

        // A slipping face on the cone's edge (|t_tr| = mu p_N to round-off:
        // its slip has stopped, e.g. at a step of the same load) keeps
        // slipping with the same traction instead of flipping with the
        // sign of the round-off; only a trial clearly inside the cone
        // sticks it again
        const bool onEdge =
            !r.slip
         && state_["contactStick"][facei] == 0
         && r.bound > 0
         && r.trial.norm() > (1 - edgeTolerance_)*r.bound;
        // Within a Newton step a face keeps its stick or slip
        const scalar stickBefore = state_["contactStick"][facei];
        const bool frozenSlip = cond.frozen && stickBefore == 0;
        const bool frozenStick = cond.frozen && stickBefore == 1;
        if ((onEdge || frozenSlip) && !r.slip)
        {
            // The return map's traction on the cone's edge
            const scalar t = r.trial.norm();
            cond.tangentialTraction[facei] =
                t > 0
              ? c4fConvert::toFoam(Eigen::Vector3d(r.bound*r.trial/t))
              : vector::zero;
            setStick(facei, 0, cond);
        }
        else if (r.slip && !frozenStick)
        {
            cond.tangentialTraction[facei] = c4fConvert::toFoam(r.traction);
            setStick(facei, 0, cond);
        }
        else
        {
            tie(facei, cond);
            setStick(facei, 1, cond);
        }
        updateSlip(state, cond, facei);
    }
}


// ************************************************************************* //
