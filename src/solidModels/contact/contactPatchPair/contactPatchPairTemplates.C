/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "Pstream.H"

template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::contactPatchPair::gatherMaster
(
    const UList<Type>& local,
    const int tag
) const
{
    tmp<Field<Type>> tall(new Field<Type>());
    Field<Type>& all = tall.ref();

    if (!Pstream::parRun())
    {
        all = local;
        return tall;
    }

    List<Field<Type>> procValues(Pstream::nProcs());
    procValues[Pstream::myProcNo()] = local;
    Pstream::gatherList(procValues, tag);
    Pstream::scatterList(procValues, tag);

    label n = 0;
    for (const Field<Type>& v : procValues)
    {
        n += v.size();
    }
    all.setSize(n);
    n = 0;
    for (const Field<Type>& v : procValues)
    {
        for (const Type& x : v)
        {
            all[n++] = x;
        }
    }
    return tall;
}


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::contactPatchPair::sumOverProcessors
(
    const Field<Type>& gathered,
    const int tag
) const
{
    tmp<Field<Type>> tsum(new Field<Type>(gathered));
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(tsum.ref(), plusEqOp<Type>(), tag);
        Pstream::listCombineScatter(tsum.ref(), tag);
    }
    return tsum;
}
