// Refinement passes: local/global ARAP iterations (2a + 2b) started from step 1, reusing the
// step-2 factor, sped up with Anderson acceleration (Walker & Ni 2011; for local/global
// geometry solvers Peng, Deng, Zhang & Liu 2018). Plain local/global converges slowly on
// the long, smooth rotation fields of a bent character (the low-frequency error shrinks by a
// factor close to 1 per pass); extrapolating from the last few passes removes most of it.
// The energy safeguard keeps the monotone descent of plain passes: an extrapolated point is
// used only if its energy is below that of the point it extrapolates from, else the pass
// falls back to the plain G(x). Everything is sequential and history-free across calls, so
// the result is a pure function of the step-1 result and the pass count.
#include "arap_solver.h"

#include <Eigen/Dense>

namespace finbook::deform::detail {
namespace {

// Passes remembered for the extrapolation: on the bars and drawings of `finbook-bench arap`
// 3 converged slightly slower, 8 and 12 no faster than 5 (measured).
constexpr int kHistory = 5;
// Before the history holds anything useful, passes 2 and 3 step past G(x) by this multiple
// of the pass's own move (over-relaxation, checked by the same energy safeguard): on the
// bars and drawings of `finbook-bench arap` it takes 3 passes from about 1.47× to 1.31× the
// converged energy, where 0.8, 1.2 and 1.5 did worse (measured).
constexpr int kOverRelaxedPasses = 3;
// Flip repair by more passes (drag): kUnfoldPatience passes in a row that leave the count of
// flipped triangles above its lowest end the repair; the rest are taken as forced by the pins.
// A drawing whose pins force folds so pays up to that many passes per event for looking.
// A fold often survives the first extra pass and opens in the second: with 1, the 20k-vertex
// drawings of the quality bench kept 11 drag flips beyond the converged pose's, with 2 (and
// two extra passes, see kMinFlipPasses in arap_solve.cpp) 4; 3 (and three extra) left 6 on
// the 9 drawings that fold.
constexpr int kUnfoldPatience = 2;
constexpr double kOverRelaxation = 1.0;

double realDot(const Eigen::Ref<const Eigen::VectorXcd> &a,
               const Eigen::Ref<const Eigen::VectorXcd> &b)
{
    // Re(aᴴb) = Σ a.re·b.re + a.im·b.im, over the doubles as one real vector.
    const Eigen::Map<const Eigen::VectorXd> x(reinterpret_cast<const double *>(a.data()),
                                              2 * a.size());
    const Eigen::Map<const Eigen::VectorXd> y(reinterpret_cast<const double *>(b.data()),
                                              2 * b.size());
    return x.dot(y);
}

double maxMagnitude(const Eigen::Ref<const Eigen::VectorXcd> &v)
{
    return v.size() > 0 ? std::sqrt(v.cwiseAbs2().maxCoeff()) : 0.0;
}

// History of the fixed-point map G (one local/global pass) in a ring buffer: columns of
// mappedSteps are ΔG = G(x_{k+1}) − G(x_k), of residualSteps ΔF with F(x) = G(x) − x.
class Accelerator {
public:
    explicit Accelerator(Workspace &w, Eigen::Index n)
        : m_w(w)
    {
        m_w.mappedSteps.resize(n, kHistory);
        m_w.residualSteps.resize(n, kHistory);
        m_w.mappedBefore.resize(n);
        m_w.residualBefore.resize(n);
    }

    // Records G(x) = mapped and F = residual of the latest pass.
    void record(const Eigen::VectorXcd &mapped, const Eigen::VectorXcd &residual)
    {
        if (m_hasPrevious) {
            const int slot = m_next;
            m_w.mappedSteps.col(slot) = mapped - m_w.mappedBefore;
            m_w.residualSteps.col(slot) = residual - m_w.residualBefore;
            for (int j = 0; j < kHistory; ++j) {
                if (j < m_count || j == slot)
                    m_gram(slot, j) = m_gram(j, slot) =
                        realDot(m_w.residualSteps.col(slot), m_w.residualSteps.col(j));
            }
            m_count = std::min(m_count + 1, kHistory);
            m_next = (m_next + 1) % kHistory;
        }
        m_w.mappedBefore = mapped;
        m_w.residualBefore = residual;
        m_hasPrevious = true;
    }

    // x = G − ΔG·θ with θ = argmin ‖F − ΔF·θ‖; false (x untouched) when there is no usable
    // history or the small system is ill-conditioned.
    bool extrapolate(const Eigen::VectorXcd &mapped, const Eigen::VectorXcd &residual,
                     Eigen::VectorXcd &x) const
    {
        if (m_count == 0)
            return false;
        const auto columns = Eigen::seqN(0, m_count);
        Eigen::MatrixXd gram = m_gram(columns, columns);
        Eigen::VectorXd rhs(m_count);
        for (int j = 0; j < m_count; ++j)
            rhs(j) = realDot(m_w.residualSteps.col(j), residual);
        // Tikhonov term relative to the diagonal: keeps nearly parallel history columns
        // from producing huge, cancelling coefficients.
        gram.diagonal().array() += 1e-10 * gram.diagonal().maxCoeff();
        const Eigen::LDLT<Eigen::MatrixXd> ldlt(gram);
        const Eigen::VectorXd theta = ldlt.solve(rhs);
        if (ldlt.info() != Eigen::Success || !theta.allFinite() ||
            !(gram.diagonal().minCoeff() > 0))
            return false;
        x = mapped;
        x.noalias() -= m_w.mappedSteps.leftCols(m_count) * theta.cast<Complex>();
        return x.allFinite();
    }

private:
    Workspace &m_w;
    Eigen::Matrix<double, kHistory, kHistory> m_gram =
        Eigen::Matrix<double, kHistory, kHistory>::Zero();
    int m_count = 0, m_next = 0;
    bool m_hasPrevious = false;
};

// The safeguard compares a candidate with the point it extrapolates from, not with the last
// result, so on rare passes the result's energy rises (seen on a strongly compressed bar).
// Two more rotation fits decide between the last two results (w.mapped holds the one
// before), so a pass never returns a worse pose than one pass fewer would have.
void keepBetterOfLastTwo(const ArapPrecompute &d, Workspace &w, bool havePrevious)
{
    if (!havePrevious)
        return;
    auto free = w.positions.head(d.freeCount);
    w.trialRotations.resize(w.rotations.size());
    const double last = fitRotations(d, w.positions, w.trialRotations, true);
    w.iterate = free;
    free = w.mapped;
    if (fitRotations(d, w.positions, w.trialRotations, true) < last)
        return; // keep the previous result
    free = w.iterate;
}

} // namespace

std::optional<DeformError> refine(const ArapPrecompute &d, Workspace &w, int passes, int flipPasses,
                                  double tolerance, double energyTolerance,
                                  const std::function<bool()> &cancelled, ArapSolveReport &report)
{
    const Eigen::Index nf = d.freeCount;
    w.refinedEnergy = 0.0;
    if (nf == 0 || passes <= 0)
        return std::nullopt;
    auto free = w.positions.head(nf);
    w.iterate = free; // x_0: the step-1 result
    double energy = fitRotations(d, w.positions, w.rotations, true);
    globalStep(d, w);
    report.passes = 1;
    Accelerator accelerator(w, nf);
    w.mapped.resize(nf);
    // Past `passes`, up to flipPasses more run while the pose has flipped triangles: an
    // unconverged pose folds where the optimum does not, and further passes unfold it.
    // Folds the optimum has too do not unfold: stop once kUnfoldPatience passes in a row
    // brought no new low in the count (see kUnfoldPatience).
    int fewestFlips = 0, passesAtFewest = 0;
    const auto unfolding = [&] {
        if (report.passes >= passes + flipPasses)
            return false;
        const int flips = countFlips(d, w.positions);
        if (report.passes == passes) {
            report.repairedTriangles = flips; // before the repair; repairFlips settles it
            fewestFlips = flips;
            passesAtFewest = passes;
        } else if (flips < fewestFlips) {
            fewestFlips = flips;
            passesAtFewest = report.passes;
        }
        return flips > 0 && report.passes - passesAtFewest < kUnfoldPatience;
    };
    while (report.passes < passes || (flipPasses > 0 && unfolding())) {
        if (cancelled && cancelled())
            return makeError(DeformErrorCode::Cancelled, "the pose solve was cancelled");
        // free = G(x); the fixed-point residual G(x) − x measures how far a pass still moves.
        w.mapped = free;
        w.residual = w.mapped - w.iterate;
        // Converged: the pass moves no vertex by more than `tolerance` and (when asked) the
        // previous one lowered the energy by no more than energyTolerance of it. Either alone
        // stops too early on thin drawings, where a pass moves little (slow, low-frequency
        // rotation fields) or a plain pass gains little while the acceleration still does.
        const bool settled = energyTolerance <= 0.0 || report.lastEnergyChange <= energyTolerance;
        if (tolerance > 0.0 && settled && maxMagnitude(w.residual) <= tolerance) {
            report.converged = true;
            break;
        }
        // The history feeds extrapolations from pass kOverRelaxedPasses on; the last pass of a
        // two-pass drag never extrapolates, so it skips the bookkeeping.
        const bool lastPass = tolerance == 0.0 && report.passes + 1 >= passes + flipPasses;
        if (!(lastPass && report.passes < kOverRelaxedPasses))
            accelerator.record(w.mapped, w.residual);
        double next = INFINITY;
        bool candidate = report.passes < kOverRelaxedPasses;
        if (candidate)
            w.iterate = w.mapped + kOverRelaxation * w.residual;
        else
            candidate = accelerator.extrapolate(w.mapped, w.residual, w.iterate);
        if (candidate) {
            free = w.iterate;
            next = fitRotations(d, w.positions, w.rotations, true);
        }
        if (!(next < energy)) { // no candidate, or it did not descend from x
            w.iterate = w.mapped;
            free = w.mapped;
            next = fitRotations(d, w.positions, w.rotations, true);
        }
        // The energy falls with every pass (the safeguard).
        report.lastEnergyChange = next > 0.0 ? (energy - next) / next : 0.0;
        energy = next;
        globalStep(d, w); // reads the rotations and the handles, not the free positions
        ++report.passes;
    }
    w.refinedEnergy = energy;
    if (tolerance > 0.0 && !report.converged) // the cap was reached: was the last pass small?
        report.converged = maxMagnitude(free - w.iterate) <= tolerance;
    if (auto error = checkGlobalStep(d, w, report))
        return error;
    // Only for a final pose: on drag poses of 57 drawings and bars it changed one result by
    // 0.4 % of its energy, and its two rotation fits cost a fifth of a pass. After passes
    // that ran to unfold flipped triangles, the last result is the unfolded one.
    if (tolerance > 0.0)
        keepBetterOfLastTwo(d, w, report.passes > 1 && report.passes <= passes);
    return std::nullopt;
}

} // namespace finbook::deform::detail
