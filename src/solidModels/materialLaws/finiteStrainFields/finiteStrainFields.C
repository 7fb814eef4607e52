/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "finiteStrainFields.H"
#include "hyperelasticLaws.H"
#include "eigenFoamConversions.H"

namespace
{

bool admissible(const Eigen::Matrix3d& F)
{
    return c4f::elasticity::checkJacobian(F) == c4f::elasticity::JacobianCheck::ok;
}

template<class FieldType>
Foam::tmp<FieldType> unnamed
(
    const Foam::word& name,
    const Foam::volTensorField& gradD,
    const typename FieldType::value_type& zero
)
{
    return Foam::tmp<FieldType>::New
    (
        Foam::IOobject
        (
            name,
            gradD.time().timeName(),
            gradD.mesh(),
            Foam::IOobject::NO_READ,
            Foam::IOobject::NO_WRITE,
            false
        ),
        gradD.mesh(),
        Foam::dimensioned<typename FieldType::value_type>
        (
            name, Foam::dimPressure, zero
        )
    );
}

} // End anonymous namespace


Foam::tmp<Foam::tensorField> Foam::finiteStrainFields::firstPiola
(
    const tensorField& gradD,
    const PK1& law
)
{
    tmp<tensorField> tP(new tensorField(gradD.size(), Zero));
    tensorField& P = tP.ref();
    forAll(gradD, i)
    {
        const Eigen::Matrix3d F =
            c4f::elasticity::deformationGradient(c4fConvert::toEigen(gradD[i]));
        P[i] = c4fConvert::toFoamTensor(law(F));
    }
    return tP;
}


Foam::tmp<Foam::symmTensorField> Foam::finiteStrainFields::cauchy
(
    const tensorField& firstPiola,
    const tensorField& gradD
)
{
    tmp<symmTensorField> ts(new symmTensorField(gradD.size(), Zero));
    symmTensorField& s = ts.ref();
    forAll(gradD, i)
    {
        const Eigen::Matrix3d F =
            c4f::elasticity::deformationGradient(c4fConvert::toEigen(gradD[i]));
        if (admissible(F))
        {
            s[i] = c4fConvert::toFoamSymm
            (
                c4f::elasticity::cauchyFromPK1(c4fConvert::toEigen(firstPiola[i]), F)
            );
        }
    }
    return ts;
}


Foam::tmp<Foam::symmTensorField> Foam::finiteStrainFields::cauchy
(
    const tensorField& gradD,
    const PK1& law
)
{
    return cauchy(firstPiola(gradD, law)(), gradD);
}


Foam::tmp<Foam::volTensorField> Foam::finiteStrainFields::firstPiola
(
    const volTensorField& gradD,
    const PK1& law
)
{
    tmp<volTensorField> tP(unnamed<volTensorField>("firstPiolaLaw", gradD, Zero));
    volTensorField& P = tP.ref();
    P.primitiveFieldRef() = firstPiola(gradD.primitiveField(), law);
    forAll(P.boundaryField(), patchi)
    {
        P.boundaryFieldRef()[patchi] =
            firstPiola(gradD.boundaryField()[patchi], law);
    }
    return tP;
}


Foam::tmp<Foam::volSymmTensorField> Foam::finiteStrainFields::cauchy
(
    const volTensorField& gradD,
    const PK1& law
)
{
    return cauchy(firstPiola(gradD, law)(), gradD);
}


Foam::tmp<Foam::volSymmTensorField> Foam::finiteStrainFields::cauchy
(
    const volTensorField& firstPiola,
    const volTensorField& gradD
)
{
    tmp<volSymmTensorField> ts(unnamed<volSymmTensorField>("sigma", gradD, Zero));
    volSymmTensorField& s = ts.ref();
    s.primitiveFieldRef() = cauchy(firstPiola.primitiveField(), gradD.primitiveField());
    forAll(s.boundaryField(), patchi)
    {
        s.boundaryFieldRef()[patchi] =
            cauchy(firstPiola.boundaryField()[patchi], gradD.boundaryField()[patchi]);
    }
    return ts;
}


Foam::label Foam::finiteStrainFields::firstInadmissibleCell
(
    const volTensorField& gradD
)
{
    forAll(gradD, celli)
    {
        if
        (
           !admissible
            (
                c4f::elasticity::deformationGradient
                (
                    c4fConvert::toEigen(gradD[celli])
                )
            )
        )
        {
            return celli;
        }
    }
    return -1;
}

// ************************************************************************* //
