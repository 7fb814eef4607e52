/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactGAMGInterfaceField.H"
#include "addToRunTimeSelectionTable.H"
#include "solidContactFvPatchVectorField.H"
#include "registerSwitch.H"

namespace Foam
{
    defineTypeNameAndDebug(contactGAMGInterfaceField, 0);
    addToRunTimeSelectionTable
    (
        GAMGInterfaceField,
        contactGAMGInterfaceField,
        lduInterfaceField
    );
    addToRunTimeSelectionTable
    (
        GAMGInterfaceField,
        contactGAMGInterfaceField,
        lduInterface
    );
}

int Foam::contactGAMGInterfaceField::coarseCoupling
(
    Foam::debug::optimisationSwitch("contactCoarseCoupling", 1)
);
registerOptSwitch
(
    "contactCoarseCoupling",
    int,
    Foam::contactGAMGInterfaceField::coarseCoupling
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactGAMGInterfaceField::contactGAMGInterfaceField
(
    const GAMGInterface& GAMGCp,
    const lduInterfaceField& fineInterface
)
:
    GAMGInterfaceField(GAMGCp, fineInterface),
    root_(nullptr),
    partner_(-1)
{
    if (const auto* coarse = isA<contactGAMGInterfaceField>(fineInterface))
    {
        root_ = coarse->root();
    }
    else
    {
        root_ = isA<solidContactFvPatchVectorField>(fineInterface);
    }
    // A patch against a rigid tool has no partner cells on any level
    if (root_ && root_->rigid())
    {
        root_ = nullptr;
    }
    if (root_)
    {
        partner_ = root_->shadowPatchIndex();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactGAMGInterfaceField::updateInterfaceMatrix
(
    solveScalarField& result,
    const bool add,
    const solveScalarField& psiInternal,
    const scalarField&,
    const direction cmpt,
    const Pstream::commsTypes
) const
{
    if (!root_ || !coarseCoupling)
    {
        return;
    }

    // The partner's faces on this level: its interface in the level's list
    // at the partner patch's index (contactFvMesh lists each contact
    // interface at its patch's index, and GAMG keeps the indices)
    const lduInterfacePtrsList& level = interface().coarseInterfaces();
    if (partner_ < 0 || partner_ >= level.size() || !level.set(partner_))
    {
        FatalErrorInFunction
            << "Contact patch " << root_->patch().name() << ": no GAMG"
            << " interface of its shadow patch (index " << partner_ << ") on"
            << " this level; the mesh must list both contact patches"
            << " (contactFvMesh)" << abort(FatalError);
    }

    root_->addNeighbours
    (
        result, add, psiInternal, cmpt, interface().faceCells(),
        level[partner_].faceCells()
    );
}


// ************************************************************************* //
