/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "Pstream.H"
#include "consistentTransfer.H"

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


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::contactPatchPair::slaveValues
(
    const UList<Type>& masterLocal
) const
{
    const Field<Type> all(gatherMaster(masterLocal));

    std::vector<std::vector<int>> faces(overlapFaces_.size());
    std::vector<std::vector<double>> weights(overlapFaces_.size());
    forAll(overlapFaces_, facei)
    {
        faces[facei].assign
        (
            overlapFaces_[facei].begin(), overlapFaces_[facei].end()
        );
        weights[facei].assign
        (
            overlapWeights_[facei].begin(), overlapWeights_[facei].end()
        );
    }

    tmp<Field<Type>> tf(new Field<Type>(overlapFaces_.size(), Zero));
    Field<Type>& f = tf.ref();
    for (direction d = 0; d < pTraits<Type>::nComponents; ++d)
    {
        const scalarField cmpt(all.component(d));
        const std::vector<double> fd
        (
            c4f::transfer::consistentTransfer
            (
                faces, weights, std::vector<double>(cmpt.begin(), cmpt.end())
            )
        );
        forAll(f, facei)
        {
            setComponent(f[facei], d) = fd[facei];
        }
    }
    return tf;
}
