/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "nitscheContactMethod.H"
#include "addToRunTimeSelectionTable.H"
#include "nitscheLaw.H"

namespace Foam
{
namespace contactMethods
{
    defineTypeNameAndDebug(nitsche, 0);
    addContactMethodToTables(nitsche);
}
}


// consistent: exact for every gamma0
const Foam::contactMethodTraits
Foam::contactMethods::nitsche::typeTraits
{
    contactMethodTraits::answerKind::exact,
    false,  // openStart
    true,  // allowsSlip
    contactMethodTraits::multiplierKind::none,
    true,  // finiteStrain
    "gamma0 10; weights equal;"
};


Foam::contactMethods::nitsche::nitsche
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    contactMethod(patch, coeffs),
    gamma0_(coeffs.get<scalar>("gamma0")),
    weights_(coeffs.get<word>("weights"))
{
    if (weights_ != "equal" && weights_ != "stiffness")
    {
        FatalIOErrorInFunction(coeffs)
            << "Invalid weights " << weights_ << " in " << coeffs.name()
            << " (contact patch " << patch.name() << "): valid are equal"
            << " ((1/2)(slave + master) of the cells' normal stress) and"
            << " stiffness (each body's by its compliance share h/K)"
            << exit(FatalIOError);
    }

    if (!c4f::contact::validNitscheParameter(gamma0_))
    {
        FatalIOErrorInFunction(coeffs)
            << "Invalid gamma0 " << gamma0_ << " in " << coeffs.name()
            << " (contact patch " << patch.name() << "): "
            << c4f::contact::describeNitscheParameterRequirement().c_str()
            << exit(FatalIOError);
    }
}


void Foam::contactMethods::nitsche::correct
(
    const contactSlaveState& state,
    contactSlaveCondition& cond
)
{
    cond.nChanged = 0;

    forAll(state.constraintGap, facei)
    {
        const vector& n = state.normal[facei];
        const scalar ss = n & state.cellStress[facei] & n;
        const scalar sm = n & state.masterCellStress[facei] & n;
        scalar sigmaN = c4f::contact::nitscheNormalStress(ss, sm);
        if (weights_ == "stiffness")
        {
            const scalar ws = c4f::contact::nitscheSlaveWeight
            (
                state.stiffness[facei], state.masterStiffness[facei]
            );
            sigmaN = ws*ss + (1 - ws)*sm;
        }
        const scalar gamma = c4f::contact::nitscheStabilisation
        (
            gamma0_, state.stiffness[facei]
        );
        const c4f::contact::NitscheValue v =
            c4f::contact::nitschePressure
            (
                state.constraintGap[facei], sigmaN, gamma
            );

        cond.pressure[facei] = carriedPressure(state, cond, facei);
        cond.clearLaw(facei);

        const bool active =
            state.inRange[facei]
         && staysOrEnters(state, cond, facei, v.pressure > 0);
        if (active)
        {
            // The law's pressing branch as a spring of compliance 1/gamma
            // about p0 = -sigma_n (its tangent, linearizeNormalLaw, where
            // it presses), held also by a face that stays in contact while
            // the law no longer presses: its reaction p0 - gamma g_N then
            // turns tensile in the solve and releases it
            cond.coupled[facei] = true;
            cond.compliance[facei] = 1/gamma;
            cond.explicitPressure[facei] = -sigmaN;

            // A tied face (stick) is consistent tangentially too: its
            // spring holds it about the mean tangential traction of the
            // two bodies' cells, -(I - n n) sigma n, with the weights of
            // sigma_n (the tangential Nitsche term of Chouly 2014, J. Math.
            // Anal. Appl. 411:329, for Tresca friction)
            // n & X: the traction (X = sigma, or P^T under finite
            // deformation, per reference area; the same for a symmetric X)
            const vector ts(n & state.cellStress[facei]);
            const vector tm(n & state.masterCellStress[facei]);
            const scalar ws =
                weights_ == "stiffness"
              ? c4f::contact::nitscheSlaveWeight
                (
                    state.stiffness[facei], state.masterStiffness[facei]
                )
              : 0.5;
            const vector sn(ws*ts + (1 - ws)*tm);
            cond.tangentialPressure0[facei] = -(sn - n*(n & sn));
        }

        cond.setActive(facei, active);
    }
}
