/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactFaceState.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::contactFaceState::find(const word& name) const
{
    forAll(names_, i)
    {
        if (names_[i] == name)
        {
            return i;
        }
    }
    return -1;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactFaceState::contactFaceState(const label size)
:
    size_(size),
    names_(),
    initial_(),
    dimensions_(),
    fields_()
{}


Foam::contactFaceState::contactFaceState(const contactFaceState& s)
:
    size_(s.size_),
    names_(s.names_),
    initial_(s.initial_),
    dimensions_(s.dimensions_.size()),
    fields_(s.fields_.size())
{
    forAll(fields_, i)
    {
        dimensions_.set(i, new dimensionSet(s.dimensions_[i]));
        fields_.set(i, new scalarField(s.fields_[i]));
    }
}


void Foam::contactFaceState::operator=(const contactFaceState& s)
{
    if (this == &s)
    {
        return;
    }
    forAll(s.names_, j)
    {
        scalarField& f = add(s.names_[j], s.initial_[j], s.dimensions_[j]);
        if (s.fields_[j].size() == size_)
        {
            f = s.fields_[j];
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalarField& Foam::contactFaceState::add
(
    const word& name,
    const scalar initial,
    const dimensionSet& dims
)
{
    const label i = find(name);
    if (i >= 0)
    {
        return fields_[i];
    }
    names_.append(name);
    initial_.append(initial);
    dimensions_.append(new dimensionSet(dims));
    fields_.append(new scalarField(size_, initial));
    return fields_.last();
}


Foam::scalarField& Foam::contactFaceState::operator[](const word& name)
{
    const label i = find(name);
    if (i < 0)
    {
        FatalErrorInFunction
            << "No contact state field " << name << "; there are "
            << names_ << abort(FatalError);
    }
    return fields_[i];
}


const Foam::scalarField& Foam::contactFaceState::operator[]
(
    const word& name
) const
{
    return const_cast<contactFaceState&>(*this)[name];
}


const Foam::dimensionSet& Foam::contactFaceState::dimensions
(
    const word& name
) const
{
    (void)operator[](name);
    return dimensions_[find(name)];
}


void Foam::contactFaceState::read(const dictionary& patchDict)
{
    forAll(names_, i)
    {
        if (patchDict.found(names_[i]))
        {
            fields_[i] = scalarField(names_[i], patchDict, size_);
        }
    }
}


void Foam::contactFaceState::write(Ostream& os) const
{
    forAll(names_, i)
    {
        fields_[i].writeEntry(names_[i], os);
    }
}


void Foam::contactFaceState::map
(
    const contactFaceState& s,
    const fvPatchFieldMapper& m
)
{
    // A face the mapper leaves unset (reconstructPar fills the faces
    // processor by processor with rmap) keeps the initial value
    size_ = m.size();
    forAll(s.names_, j)
    {
        const scalar init = s.initial_[j];
        scalarField& f = add(s.names_[j], init, s.dimensions_[j]);
        f = scalarField(size_, init);
        f.map(s.fields_[j], m);
    }
}


void Foam::contactFaceState::autoMap(const fvPatchFieldMapper& m)
{
    size_ = m.size();
    forAll(fields_, i)
    {
        fields_[i].autoMap(m);
    }
}


void Foam::contactFaceState::rmap
(
    const contactFaceState& s,
    const labelUList& addr
)
{
    forAll(s.names_, j)
    {
        add(s.names_[j], s.initial_[j], s.dimensions_[j])
            .rmap(s.fields_[j], addr);
    }
}


// ************************************************************************* //
