/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactFaceState.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
Foam::label Foam::contactFaceState::fieldSet<Type>::find
(
    const word& name
) const
{
    forAll(names, i)
    {
        if (names[i] == name)
        {
            return i;
        }
    }
    return -1;
}


template<class Type>
void Foam::contactFaceState::copySet
(
    const fieldSet<Type>& from,
    fieldSet<Type>& to
)
{
    to.names = from.names;
    to.initial = from.initial;
    to.written = from.written;
    to.dimensions.setSize(from.dimensions.size());
    to.fields.setSize(from.fields.size());
    forAll(from.fields, i)
    {
        to.dimensions.set(i, new dimensionSet(from.dimensions[i]));
        to.fields.set(i, new Field<Type>(from.fields[i]));
    }
}


template<class Type>
void Foam::contactFaceState::assignSet(const fieldSet<Type>& from)
{
    forAll(from.names, j)
    {
        Field<Type>& f = addField<Type>
        (
            from.names[j], from.initial[j], from.dimensions[j], from.written[j]
        );
        if (from.fields[j].size() == size_)
        {
            f = from.fields[j];
        }
    }
}


template<class Type>
void Foam::contactFaceState::readSet(const dictionary& patchDict)
{
    fieldSet<Type>& fs = set<Type>();
    forAll(fs.names, i)
    {
        if (fs.written[i] && patchDict.found(fs.names[i]))
        {
            fs.fields[i] = Field<Type>(fs.names[i], patchDict, size_);
        }
    }
}


template<class Type>
void Foam::contactFaceState::writeSet(Ostream& os) const
{
    const fieldSet<Type>& fs = set<Type>();
    forAll(fs.names, i)
    {
        if (fs.written[i])
        {
            fs.fields[i].writeEntry(fs.names[i], os);
        }
    }
}


template<class Type>
void Foam::contactFaceState::mapSet
(
    const fieldSet<Type>& from,
    const fvPatchFieldMapper& m
)
{
    // A face the mapper leaves unset (reconstructPar fills the faces
    // processor by processor with rmap) keeps the initial value
    forAll(from.names, j)
    {
        const Type init = from.initial[j];
        Field<Type>& f = addField<Type>
        (
            from.names[j], init, from.dimensions[j], from.written[j]
        );
        f = Field<Type>(size_, init);
        f.map(from.fields[j], m);
    }
}


template<class Type>
void Foam::contactFaceState::autoMapSet(const fvPatchFieldMapper& m)
{
    for (Field<Type>& f : set<Type>().fields)
    {
        f.autoMap(m);
    }
}


template<class Type>
void Foam::contactFaceState::rmapSet
(
    const fieldSet<Type>& from,
    const labelUList& addr
)
{
    forAll(from.names, j)
    {
        addField<Type>
        (
            from.names[j], from.initial[j], from.dimensions[j], from.written[j]
        ).rmap(from.fields[j], addr);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
Foam::Field<Type>& Foam::contactFaceState::addField
(
    const word& name,
    const Type& initial,
    const dimensionSet& dims,
    const bool written
)
{
    fieldSet<Type>& fs = set<Type>();
    const label i = fs.find(name);
    if (i >= 0)
    {
        return fs.fields[i];
    }
    fs.names.append(name);
    fs.initial.append(initial);
    fs.dimensions.append(new dimensionSet(dims));
    fs.written.append(written);
    fs.fields.append(new Field<Type>(size_, initial));
    return fs.fields.last();
}


template<class Type>
Foam::Field<Type>& Foam::contactFaceState::field(const word& name)
{
    fieldSet<Type>& fs = set<Type>();
    const label i = fs.find(name);
    if (i < 0)
    {
        FatalErrorInFunction
            << "No contact state field " << name << " of type "
            << pTraits<Type>::typeName << "; there are " << fs.names
            << abort(FatalError);
    }
    return fs.fields[i];
}


template<class Type>
const Foam::dimensionSet& Foam::contactFaceState::dimensions
(
    const word& name
) const
{
    (void)field<Type>(name);
    const fieldSet<Type>& fs = set<Type>();
    return fs.dimensions[fs.find(name)];
}


// ************************************************************************* //
