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


void Foam::frictionModel::updateSlip
(
    const contactSlaveState& state,
    const contactSlaveCondition& cond,
    const label facei
)
{
    const vectorField& R = state_.field<vector>("contactStickPoint");
    vectorField& slip = state_.field<vector>("contactSlip");

    slip[facei] = slipAtStepStart_[facei];
    if (state_["contactStick"][facei] == 0)
    {
        const vector& n = state.normal[facei];
        const vector tT
        (
            cond.tangentialTraction[facei]
        );
        const vector dR
        (
            state.relative[facei] + cond.compliance[facei]*tT - R[facei]
        );
        slip[facei] += dR - n*(n & dR);
    }
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
    slipAtStepStart_(patch.size(), Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::frictionModel::beginStep
(
    const contactSlaveState& state,
    const contactSlaveCondition& cond
)
{
    if (!hasTangentialLaw())
    {
        return;
    }

    vectorField& R = state_.field<vector>("contactStickPoint");
    const vectorField& slip = state_.field<vector>("contactSlip");
    const scalarField& stick = state_["contactStick"];

    slipAtStepStart_ = slip;
    forAll(R, facei)
    {
        if (stick[facei] < 0)
        {
            R[facei] = state.relative[facei];
        }
        else if (stick[facei] == 0)
        {
            const vector& n = state.normal[facei];
            const vector& t = state.traction[facei];
            const vector tT(t - n*(n & t));
            const vector Rnew
            (
                state.relative[facei] + cond.compliance[facei]*tT
            );
            const vector dR(Rnew - R[facei]);
            slipAtStepStart_[facei] = slip[facei] + dR - n*(n & dR);
            R[facei] = Rnew;
        }
    }
}


void Foam::frictionModel::write(Ostream& os) const
{
    if (coeffs_.size())
    {
        coeffs_.writeEntry(word(frictionName() + "Coeffs"), os);
    }
}


// ************************************************************************* //
