/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "penaltyContactMethod.H"
#include "addToRunTimeSelectionTable.H"
#include "normalContactLaws.H"

namespace Foam
{
namespace contactMethods
{
    defineTypeNameAndDebug(penalty, 0);
    addContactMethodToTables(penalty);
}
}


// a spring eps_N = penaltyScale K/h in series: the penalty offset
const Foam::contactMethodTraits
Foam::contactMethods::penalty::typeTraits
{
    contactMethodTraits::answerKind::penalty,
    false,  // openStart
    true,  // allowsSlip
    contactMethodTraits::multiplierKind::none,
    true,  // finiteStrain
    "penaltyScale 10; implicit yes; relaxationFactor 0.05;"
};


Foam::contactMethods::penalty::penalty
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    contactMethod(patch, coeffs),
    scale_(coeffs.get<scalar>("penaltyScale")),
    implicit_(coeffs.get<bool>("implicit")),
    omega_(coeffs.get<scalar>("relaxationFactor"))
{
    if (!c4f::contact::validPenalty(scale_))
    {
        FatalIOErrorInFunction(coeffs)
            << "Invalid penaltyScale " << scale_ << " in " << coeffs.name()
            << " (contact patch " << patch.name() << "): "
            << c4f::contact::describePenaltyRequirement().c_str()
            << exit(FatalIOError);
    }

    if (!(omega_ > 0 && omega_ <= 1))
    {
        FatalIOErrorInFunction(coeffs)
            << "Invalid relaxationFactor " << omega_ << " in "
            << coeffs.name() << " (contact patch " << patch.name()
            << "): it must lie in (0, 1]" << exit(FatalIOError);
    }
}


Foam::tmp<Foam::scalarField> Foam::contactMethods::penalty::epsN
(
    const contactSlaveState& state
) const
{
    tmp<scalarField> teps(new scalarField(state.constraintGap.size()));
    scalarField& eps = teps.ref();
    forAll(eps, facei)
    {
        eps[facei] = scale_*state.stiffness[facei];
    }
    return teps;
}


void Foam::contactMethods::penalty::correct
(
    const contactSlaveState& state,
    contactSlaveCondition& cond
)
{
    const scalarField eps(epsN(state));

    cond.nChanged = 0;

    forAll(state.constraintGap, facei)
    {
        bool active = false;
        cond.clearLaw(facei);

        if (!state.inRange[facei])
        {
            cond.pressure[facei] = 0;
        }
        else if (implicit_)
        {
            cond.pressure[facei] = carriedPressure(state, cond, facei);
            active = staysOrEnters
            (
                state, cond, facei,
                c4f::contact::penaltyPressure
                (
                    state.constraintGap[facei], eps[facei]
                ).pressure > 0
            );

            cond.coupled[facei] = active;
            cond.compliance[facei] = 1/eps[facei];
        }
        else
        {
            // The slave and the master get the same relaxed pressure, so
            // the forces balance in every corrector
            const scalar pNew = c4f::contact::penaltyPressure
            (
                state.constraintGap[facei], eps[facei]
            ).pressure;

            const scalar p =
                cond.pressure[facei]
              + omega_*(pNew - cond.pressure[facei]);

            active = p > 0;
            cond.explicitPressure[facei] = p;
            cond.pressure[facei] = p;
        }

        cond.setActive(facei, active);
    }
}
