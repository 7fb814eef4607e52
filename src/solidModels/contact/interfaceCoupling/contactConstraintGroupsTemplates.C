/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::contactConstraintGroups::average
(
    const UList<Type>& e,
    UList<Type>& p
) const
{
    if (!any_)
    {
        return;
    }

    Field<Type> sum(kbar_.size(), Zero);
    forAll(e, s)
    {
        if (grouped_[s])
        {
            sum[masterFace_[s]] += area_[s]*e[s];
        }
    }
    sum = pair_.sumOverProcessors(sum, tag_);

    forAll(p, s)
    {
        if (grouped_[s])
        {
            p[s] = kbarByArea_[masterFace_[s]]*sum[masterFace_[s]];
        }
    }
}


// ************************************************************************* //
