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
    tmp<Field<Type>> tall(new Field<Type>(local));
    if (masterMap_.valid())
    {
        masterMap_->distribute(tall.ref(), tag);
    }
    else if (Pstream::parRun())
    {
        FatalErrorInFunction
            << "Master patch " << master_.name() << ": master data asked for"
            << " before the pair's first update selected its faces"
            << abort(FatalError);
    }
    return tall;
}


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::contactPatchPair::masterSum
(
    const Field<Type>& gathered,
    const int tag
) const
{
    tmp<Field<Type>> tsum(new Field<Type>(gathered));
    if (masterMap_.valid())
    {
        // The map backwards, each face's contributions added on its owner
        mapDistributeBase::distribute
        (
            Pstream::commsTypes::nonBlocking,
            List<labelPair>(),
            master_.size(),
            masterMap_->constructMap(),
            false,
            masterMap_->subMap(),
            false,
            tsum.ref(),
            plusEqOp<Type>(),
            flipOp(),
            Type(Zero),
            tag
        );
    }
    return tsum;
}


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::contactPatchPair::sumOverProcessors
(
    const Field<Type>& gathered,
    const int tag
) const
{
    if (!masterMap_.valid())
    {
        return tmp<Field<Type>>(new Field<Type>(gathered));
    }
    return gatherMaster(masterSum(gathered, tag)(), tag);
}


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::contactPatchPair::slaveValues
(
    const UList<Type>& masterLocal
) const
{
    return slaveValuesGathered(gatherMaster(masterLocal)());
}


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::contactPatchPair::slaveValuesGathered
(
    const Field<Type>& all
) const
{

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
