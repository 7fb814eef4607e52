/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "constitutiveLawContactMethod.H"
#include "addToRunTimeSelectionTable.H"
#include "constitutiveContactLaw.H"
#include "linearizedNormalLaw.H"

namespace Foam
{
namespace contactMethods
{
    defineTypeNameAndDebug(constitutiveLaw, 0);
    addContactMethodToTables(constitutiveLaw);
}
}


// the law p = cN (-g)^n in series; cN and n have no default
const Foam::contactMethodTraits
Foam::contactMethods::constitutiveLaw::typeTraits
{
    contactMethodTraits::answerKind::constitutive,
    false,  // openStart
    true,  // allowsSlip
    contactMethodTraits::multiplierKind::none,
    true,  // finiteStrain
    ""
};


namespace
{
    Foam::scalar readRequired
    (
        const Foam::dictionary& coeffs,
        const Foam::fvPatch& patch,
        const char* name
    )
    {
        if (!coeffs.found(name))
        {
            FatalIOErrorInFunction(coeffs)
                << "Missing entry '" << name << "' in " << coeffs.name()
                << " (contact patch " << patch.name() << "): the law"
                << " p_N = cN (-g_N)^n needs cN and n; "
                << c4f::contact::describeConstitutiveLawRequirement().c_str()
                << Foam::exit(Foam::FatalIOError);
        }
        return coeffs.get<Foam::scalar>(name);
    }
}


Foam::contactMethods::constitutiveLaw::constitutiveLaw
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    contactMethod(patch, coeffs),
    cN_(readRequired(coeffs, patch, "cN")),
    n_(readRequired(coeffs, patch, "n"))
{
    if (!c4f::contact::validConstitutiveLaw(cN_, n_))
    {
        FatalIOErrorInFunction(coeffs)
            << "Invalid constitutive law cN " << cN_ << ", n " << n_
            << " in " << coeffs.name() << " (contact patch "
            << patch.name() << "): "
            << (
                   cN_ > 0 && std::isfinite(cN_)
                 ? "entry 'n' is invalid; "
                 : "entry 'cN' is invalid; "
               )
            << c4f::contact::describeConstitutiveLawRequirement().c_str()
            << exit(FatalIOError);
    }
}


void Foam::contactMethods::constitutiveLaw::correct
(
    const contactSlaveState& state,
    contactSlaveCondition& cond
)
{
    cond.nChanged = 0;

    forAll(state.constraintGap, facei)
    {
        const scalar g = state.constraintGap[facei];

        bool active = false;
        if (state.inRange[facei])
        {
            active = staysOrEnters(state, cond, facei, g < 0);
        }

        cond.pressure[facei] = carriedPressure(state, cond, facei);
        cond.clearLaw(facei);

        if (active)
        {
            // The point of the Newton step: the current gap; for a face
            // that carries pressure but whose gap has just opened (n > 1,
            // an overshooting corrector, where the tangent is zero) the
            // gap its pressure implies. Released there instead, every face
            // of hertzCylinder's contact let go at once after one Anderson
            // step that left all gaps 2e-7 m open, and the step cycled.
            scalar gStar = g;
            if
            (
                !(g < 0) && n_ > 1
             && cond.active[facei] && state.reaction[facei] > 0
            )
            {
                gStar =
                    c4f::contact::constitutiveGapForPressure
                    (
                        state.reaction[facei], cN_, n_
                    );
            }

            if (gStar < 0)
            {
                // The Newton step: the law's tangent at gStar
                const c4f::contact::LinearizedNormalLaw lin =
                    c4f::contact::linearizeNormalLaw
                    (
                        c4f::contact::constitutivePressure(gStar, cN_, n_),
                        gStar
                    );
                cond.coupled[facei] = lin.coupled;
                cond.compliance[facei] = lin.compliance;
                cond.explicitPressure[facei] = lin.pressure0;
                active = lin.coupled || lin.pressure0 > 0;
            }
            else if (n_ < 1)
            {
                // The limit of the tangent law as g* -> 0-: the exact
                // constraint about p0 = 0
                cond.coupled[facei] = true;
            }
            else if (n_ == 1)
            {
                // The penalty with eps = c_N
                cond.coupled[facei] = true;
                cond.compliance[facei] = 1/cN_;
            }
            else
            {
                // n > 1 at g >= 0 with no pressure carried: zero tangent
                // and zero pressure, not in contact
                active = false;
            }
        }

        cond.setActive(facei, active);
    }
}
