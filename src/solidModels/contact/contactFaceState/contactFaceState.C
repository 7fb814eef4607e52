/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactFaceState.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactFaceState::contactFaceState(const label size)
:
    size_(size),
    scalars_(),
    vectors_()
{}


Foam::contactFaceState::contactFaceState(const contactFaceState& s)
:
    size_(s.size_),
    scalars_(),
    vectors_()
{
    copySet(s.scalars_, scalars_);
    copySet(s.vectors_, vectors_);
}


void Foam::contactFaceState::operator=(const contactFaceState& s)
{
    if (this == &s)
    {
        return;
    }
    assignSet(s.scalars_);
    assignSet(s.vectors_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactFaceState::read(const dictionary& patchDict)
{
    readSet<scalar>(patchDict);
    readSet<vector>(patchDict);
}


void Foam::contactFaceState::write(Ostream& os) const
{
    writeSet<scalar>(os);
    writeSet<vector>(os);
}


void Foam::contactFaceState::map
(
    const contactFaceState& s,
    const fvPatchFieldMapper& m
)
{
    size_ = m.size();
    mapSet(s.scalars_, m);
    mapSet(s.vectors_, m);
}


void Foam::contactFaceState::autoMap(const fvPatchFieldMapper& m)
{
    size_ = m.size();
    autoMapSet<scalar>(m);
    autoMapSet<vector>(m);
}


void Foam::contactFaceState::rmap
(
    const contactFaceState& s,
    const labelUList& addr
)
{
    rmapSet(s.scalars_, addr);
    rmapSet(s.vectors_, addr);
}


// ************************************************************************* //
