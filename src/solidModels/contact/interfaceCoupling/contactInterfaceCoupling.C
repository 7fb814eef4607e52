/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactInterfaceCoupling.H"
#include "processorSum.H"
#include "solidPatchTractions.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::contactInterfaceCoupling::implicitWeights
(
    const vector& n,
    const scalar minWeight
)
{
    const scalar n1 = mag(n.x()) + mag(n.y()) + mag(n.z());
    return max(n1*cmptMag(n), vector::uniform(minWeight));
}


Foam::vector Foam::contactInterfaceCoupling::faceWeights(const label i) const
{
    return
        tied_[i]
      ? vector::one
      : implicitWeights(normal_[i], minWeight_[i]);
}


Foam::vector Foam::contactInterfaceCoupling::lawPart
(
    const label i,
    const vector& v
) const
{
    return tied_[i] ? v : vector(normal_[i]*(normal_[i] & v));
}


Foam::vector Foam::contactInterfaceCoupling::subFaceCoeffs
(
    const label i,
    const label s
) const
{
    if (!tied_[i] || coeffT_[s] == coeff_[s])
    {
        return coeff_[s]*faceWeights(i);
    }
    const vector nn(cmptMultiply(normal_[i], normal_[i]));
    return coeff_[s]*nn + coeffT_[s]*(vector::one - nn);
}


Foam::vector Foam::contactInterfaceCoupling::subFaceTraction
(
    const label i,
    const label s,
    const vector& e
) const
{
    if (!tied_[i] || coeffT_[s] == coeff_[s])
    {
        return coeff_[s]/area_[s]*e;
    }
    const vector& n = normal_[i];
    const vector eN(n*(n & e));
    return (coeff_[s]*eN + coeffT_[s]*(e - eN))/area_[s];
}


void Foam::contactInterfaceCoupling::cacheProductCoeffs()
{
    subCoeffs_.setSize(coeff_.size());
    DynamicList<label> coupled(normal_.size());
    forAll(normal_, i)
    {
        if (start_[i+1] > start_[i])
        {
            coupled.append(i);
        }
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            subCoeffs_[s] = subFaceCoeffs(i, s);
        }
    }
    coupledFaces_.transfer(coupled);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactInterfaceCoupling::contactInterfaceCoupling
(
    const contactPair& pair,
    const contactConstraintGroups::side constraintFaces
)
:
    pair_(pair),
    start_(1, 0),
    groups_(pair, constraintFaces, tag_),
    nMaster_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactInterfaceCoupling::set(const inputs& in)
{
    const fvPatch& slave = pair_.slavePatch();
    const scalarField& magS = slave.magSf();
    const labelListList& faces = pair_.overlapFaces();
    const List<scalarList>& weights = pair_.overlapWeights();

    nMaster_ = pair_.nMasterFaces();
    normal_ = in.normal;
    const vectorField& ns = pair_.slaveNormals();
    // The tie against sliding only under finite deformation: there the
    // sliding of curved surfaces moves the gap at first order
    const bool tieSliding =
        solidPatchTractions::finiteDeformation(slave.boundaryMesh().mesh());
    minWeight_.setSize(slave.size());
    forAll(minWeight_, i)
    {
        minWeight_[i] =
            tieSliding && mag(ns[i] + normal_[i]) > parallelTol_
          ? minImplicitWeight_
          : 0;
    }
    explicitForce_.setSize(slave.size());
    tied_.setSize(slave.size());
    forAll(tied_, i)
    {
        tied_[i] = in.coupled[i] && in.tied.size() && in.tied[i];
    }
    // A face coupled now and open at the last update (none at the first
    // update of a run, fresh or restarted: its faces were coupled, or not,
    // by the state it starts from)
    newlyCoupled_.setSize(slave.size());
    forAll(newlyCoupled_, i)
    {
        newlyCoupled_[i] =
            in.coupled[i] && coupled_.size() == slave.size() && !coupled_[i];
    }
    coupled_ = in.coupled;

    DynamicList<label> start(slave.size() + 1);
    DynamicList<label> mf;
    DynamicList<scalar> coeff;
    DynamicList<scalar> coeffT;
    DynamicList<vector> offset;
    DynamicList<scalar> area;
    scalarField gRefs(slave.size(), 0);
    start.append(0);

    forAll(faces, i)
    {
        const vector& n = in.normal[i];
        explicitForce_[i] =
            in.tangentialTraction.size()
          ? vector(in.tangentialTraction[i]*magS[i])
          : vector::zero;

        if (!in.coupled[i])
        {
            explicitForce_[i] += in.pressure0[i]*n*magS[i];
        }
        else
        {
            // The gap linearised about the current face displacements
            vector Dm(Zero);
            forAll(faces[i], k)
            {
                Dm += weights[i][k]*in.masterDf[faces[i][k]];
            }
            const scalar gRef = in.gap[i] - (n & (in.slaveDf[i] - Dm));
            gRefs[i] = gRef;

            const scalar rs = in.slaveDelta[i]/in.slaveK[i];
            forAll(faces[i], k)
            {
                const label j = faces[i][k];
                const scalar rm = in.masterDelta[j]/in.masterK[j];
                const scalar kij = 1/(rs + rm + in.compliance[i]);

                mf.append(j);
                area.append(weights[i][k]*magS[i]);
                coeff.append(area.last()*kij);
                const scalar CT =
                    in.tangentialCompliance.size()
                  ? in.tangentialCompliance[i]
                  : in.compliance[i];
                coeffT.append
                (
                    CT == in.compliance[i]
                  ? coeff.last()
                  : area.last()/(rs + rm + CT)
                );
                // The normal law's offset, and the explicit tractions; a
                // face that is not tied keeps their part along n
                const scalar bN = -gRef + in.compliance[i]*in.pressure0[i];
                vector bC(rs*in.slaveC[i] - rm*in.masterC[j]);
                if (in.slaveFaceCorrection.size())
                {
                    bC +=
                        in.masterFaceCorrection[j]
                      - in.slaveFaceCorrection[i];
                }
                if (tied_[i])
                {
                    // The vector gap G = gRef n - (I - n n) R_i + (D_fi -
                    // sum_j w_ij D_fj) is zero in stick: held to the stick
                    // point R_i tangentially (at the overlap's centroid),
                    // closed normally, about the tangential multiplier
                    vector R(in.stickPoint[i]);
                    if (in.stickCorrection.size())
                    {
                        R += in.stickCorrection[i][k];
                    }
                    vector b(bN*n + bC + R - n*(n & R));
                    if (in.tangentialMultiplier.size())
                    {
                        b += CT*in.tangentialMultiplier[i];
                    }
                    offset.append(b);
                }
                else
                {
                    offset.append(n*(bN + (bC & n)));
                }
            }
        }
        start.append(mf.size());
    }

    start_.transfer(start);
    masterFace_.transfer(mf);
    coeff_.transfer(coeff);
    coeffT_.transfer(coeffT);
    offset_.transfer(offset);
    area_.transfer(area);

    setGroups(in, gRefs);
    cacheProductCoeffs();

    if (in.D)
    {
        correctDeferred(*in.D, in.masterDelta/in.masterK, in.masterMagSf);
    }
}


void Foam::contactInterfaceCoupling::setGroups
(
    const inputs& in,
    const scalarField& gRef
)
{
    slaveR_ = in.slaveDelta/in.slaveK;
    const scalarField masterR(in.masterDelta/in.masterK);

    scalarList kappa(coeff_.size());
    scalarList slaveR(coeff_.size());
    forAll(slaveR_, i)
    {
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            kappa[s] = coeff_[s]/area_[s];
            slaveR[s] = slaveR_[i];
        }
    }

    groups_.set(masterFace_, area_, kappa, slaveR, masterR);

    if (!groups_.any())
    {
        return;
    }

    // A grouped sub-face's gap is its overlap's own (contactPatchPair::
    // overlapGaps: the slave face's plane against its master face's, each
    // through its centre moved by its face value), linearised about the
    // current face values: so that each master face value enters its own
    // constraint. The search's gap (the master surface through points
    // interpolated from the face values) cannot see an odd-even mode of
    // the master face values (each point averages two faces); with it the
    // grouped pressures oscillated as much as the slave's had
    const List<scalarList>& overlapGaps = pair_.overlapGaps();
    forAll(slaveR_, i)
    {
        const vector& n = normal_[i];
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            if (groups_.grouped(s))
            {
                // Its share of the group's stiffness in the matrix (see
                // contactConstraintGroups), and its own gap
                const label j = masterFace_[s];
                coeff_[s] = area_[s]*groups_.stiffness(s);
                coeffT_[s] = coeff_[s];
                offset_[s] +=
                    n
                   *(
                        gRef[i]
                      - (
                            overlapGaps[i][s - start_[i]]
                          - (n & (in.slaveDf[i] - in.masterDf[j]))
                        )
                    );
            }
        }
    }
}


void Foam::contactInterfaceCoupling::correctDeferred
(
    const vectorField& D,
    const scalarField& masterR,
    const scalarField& masterMagSf
)
{
    // Delta = r_j (t_j(Delta).n + p_ij(Delta)) is an affine map of Delta
    // with a contraction factor r_j k_ij < 1 (k_ij holds r_j in series),
    // solved to its fixed point at this D, so that the law is a function of
    // D alone, not of the law of an earlier corrector. For a soft master
    // against a stiff slave the factor is (delta_j/K_j)/(delta_i/K_i +
    // delta_j/K_j), 0.999 at 1000:1, and plain sweeps stop far from the
    // fixed point; Anderson's secant step on the sweeps is GMRES on the
    // affine map (Walker & Ni 2011) and needs about as many sweeps as the
    // map has distinct clusters of eigenvalues.
    const vectorField DM(pair_.masterCellValues(D, tag_));
    const scalarField& magSf = pair_.slavePatch().magSf();
    const List<vector> base(offset_);
    const label nSub = offset_.size();
    std::vector<double> x(3*nSub, 0.0), g(3*nSub), xNext;
    List<vector> p;
    vectorField F;

    scalar baseScale = 0;
    for (const vector& b : base)
    {
        baseScale = max(baseScale, cmptMax(cmptMag(b)));
    }
    reduce(baseScale, maxOp<scalar>());

    c4f::coupling::AndersonParameters params;
    params.depth = maxDeferredDepth_;
    c4f::coupling::AndersonAcceleration anderson
    (
        params,
        processorSumReduction()
    );

    nDeferredIter_ = 0;
    for (label iter = 0; iter < maxDeferredIter_; ++iter)
    {
        forAll(offset_, s)
        {
            offset_[s] = base[s] + vector(x[3*s], x[3*s + 1], x[3*s + 2]);
        }
        slaveForces(D, DM, F, p);
        const vectorField TM
        (
            pair_.sumOverProcessors(masterTransfer(F, p)(), tag_)/masterMagSf
        );

        scalar change = 0;
        forAll(normal_, i)
        {
            for (label s = start_[i]; s < start_[i+1]; ++s)
            {
                // Delta_ij = r_j (t_j + t_ij), the part the law acts on
                vector d(masterR[masterFace_[s]]*(TM[masterFace_[s]] + p[s]));
                if (groups_.grouped(s))
                {
                    // A grouped sub-face's traction is not its slave face's
                    // either: the averaged gap takes the slave face value
                    // the face's traction gives, as the master's
                    d -= slaveR_[i]*(F[i]/magSf[i] - p[s]);
                }
                d = lawPart(i, d);
                for (direction c = 0; c < 3; ++c)
                {
                    g[3*s + c] = d[c];
                    change = max(change, mag(g[3*s + c] - x[3*s + c]));
                }
            }
        }
        ++nDeferredIter_;

        // Round-off of the correction itself bounds what can be reached
        scalar scale = baseScale;
        for (const double v : g)
        {
            scale = max(scale, mag(v));
        }
        if
        (
            returnReduce(change, maxOp<scalar>())
         <= 1e-12*returnReduce(scale, maxOp<scalar>())
        )
        {
            // offset_ holds base + x, whose map value g is within the
            // tolerance of x
            break;
        }

        anderson.update(x, g, xNext);
        x.swap(xNext);
    }
}


void Foam::contactInterfaceCoupling::slaveForces
(
    const vectorField& D,
    const vectorField& DM,
    vectorField& F,
    List<vector>& p
) const
{
    const labelUList& fc = pair_.slavePatch().faceCells();

    // Each sub-face's own law t_s = kappa_s e_s (along n, or whole for a
    // tied face), then the groups' shared traction from the e_s of their
    // sub-faces
    List<vector> e(coeff_.size());
    p.setSize(coeff_.size());
    forAll(normal_, i)
    {
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            e[s] = lawPart(i, DM[masterFace_[s]] - D[fc[i]] + offset_[s]);
            p[s] = subFaceTraction(i, s, e[s]);
        }
    }
    groups_.average(e, p);

    F.setSize(normal_.size());
    forAll(normal_, i)
    {
        F[i] = explicitForce_[i];
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            F[i] += area_[s]*p[s];
        }
    }
}


Foam::tmp<Foam::vectorField> Foam::contactInterfaceCoupling::masterTransfer
(
    const vectorField& slaveForce,
    const List<vector>& p
) const
{
    // The master receives each slave face's force by the overlap weights,
    // as one pressure per slave face; a grouped sub-face's force goes to
    // its own master face (the transpose of the gap averaged over it)
    const labelListList& faces = pair_.overlapFaces();
    const List<scalarList>& weights = pair_.overlapWeights();

    tmp<vectorField> tFM(new vectorField(nMaster_, Zero));
    vectorField& FM = tFM.ref();
    forAll(faces, i)
    {
        vector Fi(slaveForce[i]);
        if (groups_.any())
        {
            for (label s = start_[i]; s < start_[i+1]; ++s)
            {
                if (groups_.grouped(s))
                {
                    const vector Fs(area_[s]*p[s]);
                    FM[masterFace_[s]] -= Fs;
                    Fi -= Fs;
                }
            }
        }
        forAll(faces[i], k)
        {
            FM[faces[i][k]] -= weights[i][k]*Fi;
        }
    }
    return tFM;
}


Foam::scalar Foam::contactInterfaceCoupling::directionStiffness
(
    const vector& e
) const
{
    scalar k = 0;
    forAll(normal_, i)
    {
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            k += coeff_[s]*sqr(normal_[i] & e);
        }
    }
    return returnReduce(k, sumOp<scalar>());
}


Foam::tmp<Foam::vectorField> Foam::contactInterfaceCoupling::slaveDiag() const
{
    tmp<vectorField> td(new vectorField(normal_.size(), Zero));
    vectorField& d = td.ref();
    for (const label i : coupledFaces_)
    {
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            d[i] += subCoeffs_[s];
        }
    }
    return td;
}


Foam::tmp<Foam::vectorField> Foam::contactInterfaceCoupling::masterDiag() const
{
    vectorField d(nMaster_, Zero);
    for (const label i : coupledFaces_)
    {
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            d[masterFace_[s]] += subCoeffs_[s];
        }
    }
    return pair_.masterSum(d, tag_);
}


Foam::tmp<Foam::scalarField> Foam::contactInterfaceCoupling::slaveNeighbour
(
    const UList<solveScalar>& psi,
    const direction cmpt,
    const labelUList& masterCells
) const
{
    const scalarField psiM(pair_.masterCellValues(psi, masterCells, tag_));

    tmp<scalarField> tnb(new scalarField(normal_.size(), 0));
    scalarField& nb = tnb.ref();
    for (const label i : coupledFaces_)
    {
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            nb[i] += subCoeffs_[s][cmpt]*psiM[masterFace_[s]];
        }
    }
    return tnb;
}


Foam::tmp<Foam::scalarField> Foam::contactInterfaceCoupling::masterNeighbour
(
    const UList<solveScalar>& psi,
    const direction cmpt,
    const labelUList& fc
) const
{
    scalarField nb(nMaster_, 0);
    for (const label i : coupledFaces_)
    {
        for (label s = start_[i]; s < start_[i+1]; ++s)
        {
            nb[masterFace_[s]] += subCoeffs_[s][cmpt]*psi[fc[i]];
        }
    }
    return pair_.masterSum(nb, tag_);
}


void Foam::contactInterfaceCoupling::forces
(
    const vectorField& D,
    vectorField& slaveForce,
    vectorField& masterForce,
    scalarField& slavePressure,
    const bool assembly
) const
{
    List<vector> p;
    slaveForces(D, pair_.masterCellValues(D, tag_), slaveForce, p);

    slavePressure = (slaveForce & normal_)/pair_.slavePatch().magSf();

    // The lagged part of an entering face's law at its touching state
    // (Description, "A face that enters"): only in the matrix's explicit
    // part, the forces of the solved state stay the law's
    if (assembly)
    {
        forAll(normal_, i)
        {
            if (!newlyCoupled_[i] || tied_[i])
            {
                continue;
            }
            // A grouped sub-face keeps its group's law (and the transfer
            // takes p only for those): the rest goes with the face's force
            const vector& n = normal_[i];
            const vector nLag(n - cmptMultiply(faceWeights(i), n));
            for (label s = start_[i]; s < start_[i+1]; ++s)
            {
                if (!groups_.any() || !groups_.grouped(s))
                {
                    slaveForce[i] -= area_[s]*(n & p[s])*nLag;
                }
            }
        }
    }

    masterForce = pair_.masterSum(masterTransfer(slaveForce, p)(), tag_);
}
