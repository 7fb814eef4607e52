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


void Foam::frictionModels::coulomb::correct
(
    const contactSlaveState& state,
    contactSlaveCondition& cond
)
{
    forAll(cond.tied, facei)
    {
        cond.tied[facei] = false;
        cond.tangentialTraction[facei] = Zero;
        cond.tangentialMultiplier[facei] = Zero;

        if (!cond.coupled[facei])
        {
            setStick(facei, -1, cond);
            updateSlip(state, cond, facei);
            continue;
        }

        const vector& n = state.normal[facei];
        const vector& t = state.traction[facei];
        const vector tT(t - n*(n & t));
        const vector GT(tangentialGap(state, cond, facei));

        const c4f::contact::CoulombResult r = c4f::contact::coulombReturnMap
        (
            c4fConvert::toEigen(n),
            c4fConvert::toEigen(tT),
            c4fConvert::toEigen(GT),
            state.reaction[facei],
            mu_,
            state.pairStiffness[facei]
        );

        // A slipping face on the cone's edge (|t_tr| = mu p_N to round-off:
        // its slip has stopped, e.g. at a step of the same load) keeps
        // slipping with the same traction instead of flipping with the
        // sign of the round-off; only a trial clearly inside the cone
        // sticks it again
        const scalar bound = mu_*max(state.reaction[facei], scalar(0));
        const vector trial(tT - state.pairStiffness[facei]*GT);
        const bool onEdge =
            !r.slip
         && state_["contactStick"][facei] == 0
         && bound > 0
         && mag(trial) > (1 - edgeTolerance_)*bound;
        if (onEdge)
        {
            cond.tangentialTraction[facei] = bound*trial/mag(trial);
            setStick(facei, 0, cond);
        }
        else if (r.slip)
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
