#include "Preintegrator.h"

#include "Parallel.h"
#include "PhaseFunction.h"
#include "Random.h"
#include "Vec3.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>

namespace avs
{

namespace
{

// Distance from p (inside or on the unit sphere) along the unit direction d to the sphere.
inline double ExitDistance(const Vec3& p, const Vec3& d)
{
  const double b = Dot(p, d);
  const double c = Dot(p, p) - 1.0;
  const double disc = std::max(0.0, b * b - c);
  return std::max(0.0, -b + std::sqrt(disc));
}

constexpr double RouletteThreshold = 0.1;
constexpr int MaximumOrder = 1000000;
constexpr std::size_t MaximumSplitStack = 4096;
constexpr int MaximumCopies = 8;

// Running sums for a set of estimates.
struct Accumulator
{
  std::vector<double> Sum, SumSq;
  explicit Accumulator(std::size_t n = 0)
    : Sum(n, 0.0)
    , SumSq(n, 0.0)
  {
  }
  void Add(const std::vector<double>& x)
  {
    for (std::size_t i = 0; i < x.size(); ++i)
    {
      this->Sum[i] += x[i];
      this->SumSq[i] += x[i] * x[i];
    }
  }
  double Mean(std::size_t i, double n) const { return this->Sum[i] / n; }
  double StandardError(std::size_t i, double n) const
  {
    if (n < 2)
    {
      return 0.0;
    }
    const double m = this->Sum[i] / n;
    const double var = std::max(0.0, (this->SumSq[i] / n - m * m) * n / (n - 1));
    return std::sqrt(var / n);
  }
};

// A path waiting on the splitting stack of the F paths.
struct SplitState
{
  Vec3 X, Dir;
  double Beta;
  int Order;
};

// Traces the paths of one (tau, g) cell. Distances are in units of the ball's radius.
//
// Every contribution of scattering order k + 1 is a two-dimensional integral over the direction
// w leaving vertex k (towards the sensor's side of the path) and the distance s to vertex k + 1,
// where the light is connected. It is estimated with two strategies combined by the balance
// heuristic: (1) w from the phase function at vertex k and s from the truncated exponential
// (the path's own continuation), (2) w from the phase function around the light's direction
// and s uniform on the chord. The weighted estimate f / (p1 pe + p2 pu) never exceeds the
// smaller of the two ratios, which removes the spikes a strongly peaked phase function gives
// plain next-event estimation, and the uniform distances handle deep penetration towards the
// light. Vertex k carries albedo^k, so one path serves every albedo node.
class CellTracer
{
public:
  CellTracer(const ScatteringTableAxes& axes, double tau, double g)
    : Axes(axes)
    , Tau(tau)
    , G(g)
  {
    for (int i = 0; i < axes.NumberOfTheta; ++i)
    {
      const double th = axes.Theta(i);
      this->CosTheta.push_back(std::cos(th));
      this->SinTheta.push_back(std::sin(th));
    }
    for (int l = 0; l < axes.NumberOfAlbedo; ++l)
    {
      this->Albedo.push_back(axes.Albedo(l));
    }
    this->PathEstimate.assign(
      static_cast<std::size_t>(axes.NumberOfTheta) * axes.NumberOfAlbedo, 0.0);
    this->Powers.assign(axes.NumberOfAlbedo, 1.0);
    this->Order.assign(axes.NumberOfTheta, 0.0);
  }

  // One backward path for A; fills PathEstimate (theta fastest, one row per albedo node), already
  // divided by 2 tau. Returns the number of vertices.
  std::uint64_t TraceA(Random& rng)
  {
    std::fill(this->PathEstimate.begin(), this->PathEstimate.end(), 0.0);
    const int nTheta = this->Axes.NumberOfTheta;
    // Light directions for this path: theta around the exit direction +z, one random azimuth
    // (the answer does not depend on it, by symmetry).
    const double phi = 2.0 * Pi * rng.Uniform();
    const double cp = std::cos(phi), sp = std::sin(phi);
    this->Lights.resize(nTheta);
    for (int i = 0; i < nTheta; ++i)
    {
      this->Lights[i] = { this->SinTheta[i] * cp, this->SinTheta[i] * sp, this->CosTheta[i] };
    }
    std::fill(this->Powers.begin(), this->Powers.end(), 1.0);

    // Order 1: the direction is fixed (radially inwards from the exit point); MIS over distance.
    const Vec3 x0{ 0, 0, 1 };
    Vec3 dir{ 0, 0, -1 };
    const double chord = 2.0;
    const double pCollide = -std::expm1(-this->Tau * chord);
    const double sExp = std::min(chord, -std::log1p(-rng.Uniform() * pCollide) / this->Tau);
    const double sUni = chord * rng.Uniform();
    for (int i = 0; i < nTheta; ++i)
    {
      const double phase = HenyeyGreenstein(this->CosTheta[i], this->G);
      double sum = 0.0;
      for (double s : { sExp, sUni })
      {
        const Vec3 x = x0 + dir * s;
        const double pe = this->Tau * std::exp(-this->Tau * s) / pCollide;
        const double f =
          this->Tau * std::exp(-this->Tau * (s + ExitDistance(x, -this->Lights[i]))) * phase;
        sum += f / (pe + 1.0 / chord);
      }
      this->Order[i] = sum;
    }
    this->AddOrder();
    Vec3 x = x0 + dir * sExp;
    double beta = pCollide;
    std::uint64_t vertices = 1;
    for (int order = 2; order <= MaximumOrder; ++order)
    {
      if (!this->Step(rng, x, dir, beta, this->Lights))
      {
        break;
      }
      this->AddOrder();
      ++vertices;
      if (!this->Roulette(rng, beta))
      {
        break;
      }
    }
    const double norm = 1.0 / (2.0 * this->Tau);
    for (double& v : this->PathEstimate)
    {
      v *= norm;
    }
    return vertices;
  }

  // One backward path for the scattered part of F (the irradiance through the tangent plane at
  // the forward pole); fills `estimate`, one value per albedo node.
  std::uint64_t TraceF(Random& rng, std::vector<double>& estimate)
  {
    const int nAlbedo = this->Axes.NumberOfAlbedo;
    estimate.assign(nAlbedo, 0.0);
    const Vec3 light{ 0, 0, 1 };
    this->Lights.assign(1, light);
    std::fill(this->Powers.begin(), this->Powers.end(), 1.0);
    const Vec3 xf{ 0, 0, 1 };

    // Order 1: exit direction w (light leaves along w, the path goes along -w), MIS between
    // (cosine-distributed w, exponential s) and (w from the phase function around the light,
    // uniform s). The integrand is cos(w) sigma_s T(s) p(light . w) exp(-tau b).
    auto orderOne = [&](const Vec3& w, double s)
    {
      const double cosW = w.z;
      if (!(cosW > 0.0))
      {
        return 0.0;
      }
      const double chord = 2.0 * cosW;
      if (s > chord)
      {
        return 0.0;
      }
      const Vec3 x = xf - w * s;
      const double phase = HenyeyGreenstein(Dot(light, w), this->G);
      const double f =
        cosW * this->Tau * std::exp(-this->Tau * (s + ExitDistance(x, -light))) * phase;
      const double pe = this->Tau * std::exp(-this->Tau * s) / -std::expm1(-this->Tau * chord);
      return f / (cosW / Pi * pe + phase / chord);
    };
    // Strategy (c): cosine-distributed; also the path's continuation.
    const double u1 = rng.Uniform(), u2 = rng.Uniform();
    const double cosT = std::sqrt(1.0 - u1), sinT = std::sqrt(u1);
    const Vec3 wc{ sinT * std::cos(2 * Pi * u2), sinT * std::sin(2 * Pi * u2), cosT };
    const double chordC = 2.0 * cosT;
    const double pCollide = -std::expm1(-this->Tau * chordC);
    const double sc = std::min(chordC, -std::log1p(-rng.Uniform() * pCollide) / this->Tau);
    double first = pCollide > 0.0 ? orderOne(wc, sc) : 0.0;
    // Strategy (h): phase-distributed around the light, uniform distance.
    const PhaseSample ph = SampleHenyeyGreenstein(light, this->G, rng.Uniform(), rng.Uniform());
    const Vec3 wh = Normalize(ph.Direction);
    if (wh.z > 0.0)
    {
      first += orderOne(wh, 2.0 * wh.z * rng.Uniform());
    }
    else
    {
      rng.Uniform();
    }
    this->Order[0] = first;
    this->AddOrderInto(estimate);
    if (!(pCollide > 0.0))
    {
      return 0;
    }
    // Higher orders. Deep penetration towards the lit side (z = -1) is helped by a weight
    // window on the importance I(z) = exp(k (1 - z) / 2): a path whose weight times importance
    // grows past twice the reference splits into copies, one that falls below half of it plays
    // Russian roulette. Both keep the estimate unbiased.
    const double k = this->ImportanceSlope;
    auto importance = [k](const Vec3& p) { return std::exp(0.5 * k * (1.0 - p.z)); };
    const double reference = Pi * importance(xf);
    std::vector<SplitState>& stack = this->Stack;
    stack.clear();
    stack.push_back({ xf - wc * sc, -wc, Pi * pCollide, 1 });
    std::uint64_t vertices = 1;
    while (!stack.empty())
    {
      SplitState st = stack.back();
      stack.pop_back();
      for (int order = st.Order + 1; order <= MaximumOrder; ++order)
      {
        if (!this->Step(rng, st.X, st.Dir, st.Beta, this->Lights))
        {
          break;
        }
        for (int l = 0; l < nAlbedo; ++l)
        {
          estimate[l] += std::pow(this->Albedo[l], order) * this->Order[0];
        }
        ++vertices;
        const double w = st.Beta * importance(st.X);
        if (w > 2.0 * reference && stack.size() < MaximumSplitStack)
        {
          const int copies = std::min(static_cast<int>(w / reference), MaximumCopies);
          st.Beta /= copies;
          for (int c = 1; c < copies; ++c)
          {
            stack.push_back({ st.X, st.Dir, st.Beta, order });
          }
        }
        else if (w < 0.5 * reference)
        {
          if (rng.Uniform() * reference >= w)
          {
            break;
          }
          st.Beta = reference / importance(st.X);
        }
      }
    }
    return vertices;
  }

  /// Slope k of the F paths' importance exp(k (1 - z) / 2); 0 disables the weight window.
  double ImportanceSlope = 0.0;

  std::vector<double> PathEstimate;

private:
  // From vertex x (reached along dir, weight beta without albedo): estimates the next order's
  // contribution for every light into Order[], then moves the path to its next vertex.
  bool Step(Random& rng, Vec3& x, Vec3& dir, double& beta, const std::vector<Vec3>& lights)
  {
    // Strategy 1: the path's own continuation.
    const PhaseSample ps = SampleHenyeyGreenstein(dir, this->G, rng.Uniform(), rng.Uniform());
    const Vec3 w1 = Normalize(ps.Direction);
    const double chord1 = ExitDistance(x, w1);
    const double pCollide1 = -std::expm1(-this->Tau * chord1);
    if (!(chord1 > 0.0) || !(pCollide1 > 0.0))
    {
      return false;
    }
    const double s1 = std::min(chord1, -std::log1p(-rng.Uniform() * pCollide1) / this->Tau);
    Vec3 x1 = x + w1 * s1;
    const double r2 = Dot(x1, x1);
    if (r2 > 1.0)
    {
      x1 = x1 * (1.0 / std::sqrt(r2));
    }
    const double p1 = ps.Pdf;
    const double t1 = this->Tau * std::exp(-this->Tau * s1);
    const double pe1 = t1 / pCollide1;
    const double pu1 = 1.0 / chord1;
    const std::size_t n = lights.size();
    for (std::size_t i = 0; i < n; ++i)
    {
      const Vec3& light = lights[i];
      // Strategy 1 for this light.
      const double p2 = HenyeyGreenstein(-Dot(light, w1), this->G);
      const double f1 = p1 * t1 * p2 * std::exp(-this->Tau * ExitDistance(x1, -light));
      double sum = f1 / (p1 * pe1 + p2 * pu1);
      // Strategy 2: towards the light, uniform distance.
      const PhaseSample qs = SampleHenyeyGreenstein(-light, this->G, rng.Uniform(), rng.Uniform());
      const Vec3 w2 = Normalize(qs.Direction);
      const double chord2 = ExitDistance(x, w2);
      const double u = rng.Uniform();
      if (chord2 > 0.0)
      {
        const double s2 = u * chord2;
        const Vec3 x2 = x + w2 * s2;
        const double q1 = HenyeyGreenstein(Dot(w2, dir), this->G);
        const double q2 = qs.Pdf;
        const double t2 = this->Tau * std::exp(-this->Tau * s2);
        const double pe2 = t2 / -std::expm1(-this->Tau * chord2);
        const double f2 = q1 * t2 * q2 * std::exp(-this->Tau * ExitDistance(x2, -light));
        sum += f2 / (q1 * pe2 + q2 / chord2);
      }
      this->Order[i] = beta * sum;
    }
    x = x1;
    dir = w1;
    beta *= pCollide1;
    return true;
  }

  bool Roulette(Random& rng, double& beta)
  {
    if (beta < RouletteThreshold)
    {
      if (rng.Uniform() * RouletteThreshold >= beta)
      {
        return false;
      }
      beta = RouletteThreshold;
    }
    return true;
  }

  // Multiplies the albedo powers by one more vertex and adds Order[] into PathEstimate.
  void AddOrder()
  {
    const int nTheta = this->Axes.NumberOfTheta;
    for (int l = 0; l < this->Axes.NumberOfAlbedo; ++l)
    {
      this->Powers[l] *= this->Albedo[l];
      const double w = this->Powers[l];
      if (w == 0.0)
      {
        continue;
      }
      double* row = this->PathEstimate.data() + static_cast<std::size_t>(l) * nTheta;
      for (int i = 0; i < nTheta; ++i)
      {
        row[i] += w * this->Order[i];
      }
    }
  }

  void AddOrderInto(std::vector<double>& estimate)
  {
    for (int l = 0; l < this->Axes.NumberOfAlbedo; ++l)
    {
      this->Powers[l] *= this->Albedo[l];
      estimate[l] += this->Powers[l] * this->Order[0];
    }
  }

  const ScatteringTableAxes& Axes;
  double Tau;
  double G;
  std::vector<double> CosTheta, SinTheta, Albedo, Powers, Order;
  std::vector<Vec3> Lights;
  std::vector<SplitState> Stack;
};

struct CellResult
{
  std::uint64_t PathsA = 0, PathsF = 0, Vertices = 0;
  bool AtLimit = false;
};

CellResult ComputeCell(const PreintegrationSettings& settings,
  ScatteringTable& table,
  int j,
  int k,
  double thresholdA,
  double thresholdF,
  std::mutex& tableMutex)
{
  const auto& ax = settings.Axes;
  const double tau = ax.Tau(j);
  const double g = ax.Anisotropy(k);
  const int nTheta = ax.NumberOfTheta;
  const int nAlbedo = ax.NumberOfAlbedo;
  CellResult result;
  if (tau == 0.0)
  {
    std::lock_guard<std::mutex> lock(tableMutex);
    for (int l = 0; l < nAlbedo; ++l)
    {
      for (int i = 0; i < nTheta; ++i)
      {
        table.A[table.AIndex(i, j, k, l)] =
          static_cast<float>(ax.Albedo(l) * HenyeyGreenstein(std::cos(ax.Theta(i)), g));
      }
      table.F[table.FIndex(j, k, l)] = 1.0f;
    }
    return result;
  }
  CellTracer tracer(ax, tau, g);
  // Importance slope of the F paths: 1.4 log(1 / F), with F from a diffusion estimate of the
  // transmission through the ball's transport optical diameter. The factor 1.4 was measured:
  // over slopes 0.7-2.5 times log(1 / F), 1.3-1.6 gave the smallest variance times run time in
  // thick cells (tau 3-32, g = -0.95 and 0.05), about twice better than 1.0.
  tracer.ImportanceSlope = 1.4 * std::log1p(1.5 * tau * (1.0 - g));
  const std::uint64_t cell = table.CellIndex(j, k);
  const double direct = std::exp(-2.0 * tau);

  // A: batches until every significant entry meets the target or the budget is spent.
  Accumulator accA(static_cast<std::size_t>(nTheta) * nAlbedo);
  for (std::uint64_t batch = 0;; ++batch)
  {
    Random rng(HashSeed(settings.Seed, 2 * cell, batch), cell);
    for (std::uint64_t p = 0; p < settings.BatchSize; ++p)
    {
      result.Vertices += tracer.TraceA(rng);
      accA.Add(tracer.PathEstimate);
    }
    result.PathsA += settings.BatchSize;
    if (result.PathsA < settings.MinimumPaths)
    {
      continue;
    }
    const double n = static_cast<double>(result.PathsA);
    double worst = 0.0;
    for (std::size_t e = 0; e < accA.Sum.size(); ++e)
    {
      const double m = accA.Mean(e, n);
      if (m >= thresholdA)
      {
        worst = std::max(worst, accA.StandardError(e, n) / m);
      }
    }
    if (worst <= settings.TargetRelativeError)
    {
      break;
    }
    if (result.PathsA >= settings.MaximumPaths)
    {
      result.AtLimit = true;
      break;
    }
  }
  // F: likewise, with its own (larger) budget; its paths are much cheaper.
  Accumulator accF(nAlbedo);
  std::vector<double> f;
  for (std::uint64_t batch = 0;; ++batch)
  {
    Random rng(HashSeed(settings.Seed, 2 * cell + 1, batch), cell);
    for (std::uint64_t p = 0; p < settings.BatchSize; ++p)
    {
      result.Vertices += tracer.TraceF(rng, f);
      accF.Add(f);
    }
    result.PathsF += settings.BatchSize;
    if (result.PathsF < settings.MinimumPaths)
    {
      continue;
    }
    const double n = static_cast<double>(result.PathsF);
    double worst = 0.0;
    for (int l = 0; l < nAlbedo; ++l)
    {
      const double fm = direct + accF.Mean(l, n);
      if (fm >= thresholdF)
      {
        worst = std::max(worst, accF.StandardError(l, n) / fm);
      }
    }
    if (worst <= settings.TargetRelativeError)
    {
      break;
    }
    if (result.PathsF >= settings.MaximumPathsF)
    {
      result.AtLimit = true;
      break;
    }
  }
  const double nA = static_cast<double>(result.PathsA);
  const double nF = static_cast<double>(result.PathsF);
  // The table is written under the lock so that a checkpoint never sees half a cell.
  std::lock_guard<std::mutex> lock(tableMutex);
  for (int l = 0; l < nAlbedo; ++l)
  {
    for (int i = 0; i < nTheta; ++i)
    {
      const std::size_t e = static_cast<std::size_t>(l) * nTheta + i;
      table.A[table.AIndex(i, j, k, l)] = static_cast<float>(accA.Mean(e, nA));
      table.AError[table.AIndex(i, j, k, l)] = static_cast<float>(accA.StandardError(e, nA));
    }
    table.F[table.FIndex(j, k, l)] = static_cast<float>(direct + accF.Mean(l, nF));
    table.FError[table.FIndex(j, k, l)] = static_cast<float>(accF.StandardError(l, nF));
  }
  table.PathsA[cell] = result.PathsA;
  table.PathsF[cell] = result.PathsF;
  return result;
}

// The table's largest A is analytic: at tau = 0, albedo 1, theta = 0 and the largest |g|.
double PeakA(const ScatteringTableAxes& axes)
{
  double peak = 0.0;
  for (int k = 0; k < axes.NumberOfAnisotropy; ++k)
  {
    peak = std::max(peak, HenyeyGreenstein(1.0, axes.Anisotropy(k)));
  }
  return peak;
}

} // namespace

bool CellMeetsTarget(const ScatteringTable& table, int j, int k, double threshold, double target)
{
  const auto& ax = table.Axes;
  const std::size_t cell = table.CellIndex(j, k);
  if (ax.Tau(j) > 0.0 && table.PathsA[cell] == 0 && table.PathsF[cell] == 0)
  {
    return false; // never computed
  }
  const double thresholdA = threshold * PeakA(ax);
  for (int l = 0; l < ax.NumberOfAlbedo; ++l)
  {
    for (int i = 0; i < ax.NumberOfTheta; ++i)
    {
      const std::size_t e = table.AIndex(i, j, k, l);
      if (table.A[e] >= thresholdA && table.AError[e] > target * table.A[e])
      {
        return false;
      }
    }
    const std::size_t f = table.FIndex(j, k, l);
    if (table.F[f] >= threshold && table.FError[f] > target * table.F[f])
    {
      return false;
    }
  }
  return true;
}

ScatteringTable Preintegrate(const PreintegrationSettings& settings,
  PreintegrationStatistics* statistics)
{
  const auto start = std::chrono::steady_clock::now();
  ScatteringTable table;
  table.Allocate(settings.Axes);
  table.Seed = settings.Seed;
  table.TargetRelativeError = settings.TargetRelativeError;

  const ScatteringTable* refine =
    settings.Refine && settings.Refine->Axes == settings.Axes ? settings.Refine : nullptr;
  double earlierSeconds = 0.0;
  if (refine)
  {
    table.A = refine->A;
    table.AError = refine->AError;
    table.F = refine->F;
    table.FError = refine->FError;
    table.PathsA = refine->PathsA;
    table.PathsF = refine->PathsF;
    earlierSeconds = refine->GenerationSeconds;
  }
  else
  {
    // Cells not computed (outside a requested subset, or not yet at a checkpoint) keep F = 1
    // and no paths, so that the table stays loadable and a refinement computes them.
    std::fill(table.F.begin(), table.F.end(), 1.0f);
  }
  std::vector<std::pair<int, int>> cells = settings.Cells;
  if (cells.empty())
  {
    for (int k = 0; k < settings.Axes.NumberOfAnisotropy; ++k)
    {
      for (int j = 0; j < settings.Axes.NumberOfTau; ++j)
      {
        cells.emplace_back(j, k);
      }
    }
  }
  if (refine)
  {
    // Analytic cells (tau = 0) cost nothing and are always written again.
    cells.erase(std::remove_if(cells.begin(),
                  cells.end(),
                  [&](const std::pair<int, int>& c)
                  {
                    return settings.Axes.Tau(c.first) > 0.0 &&
                      CellMeetsTarget(*refine,
                        c.first,
                        c.second,
                        settings.SignificanceThreshold,
                        settings.TargetRelativeError);
                  }),
      cells.end());
  }
  // Expensive cells (large tau) first, for better load balance; but when refining, cheap ones
  // first, so that a refinement cut short (see Checkpoint) has finished as many cells as it could.
  std::stable_sort(cells.begin(),
    cells.end(),
    [refine](const std::pair<int, int>& a, const std::pair<int, int>& b)
    { return refine ? a.first < b.first : a.first > b.first; });

  // Significance thresholds relative to the table's largest values, which are analytic (F peaks
  // at tau = 0 with F = 1).
  const double thresholdA = settings.SignificanceThreshold * PeakA(settings.Axes);
  const double thresholdF = settings.SignificanceThreshold * 1.0;

  std::mutex mutex;
  std::size_t done = 0;
  auto lastCheckpoint = start;
  PreintegrationStatistics stats;
  stats.CellsComputed = cells.size();
  ParallelFor(
    static_cast<std::int64_t>(cells.size()),
    [&](std::int64_t b, std::int64_t e)
    {
      for (std::int64_t c = b; c < e; ++c)
      {
        const CellResult r = ComputeCell(
          settings, table, cells[c].first, cells[c].second, thresholdA, thresholdF, mutex);
        std::lock_guard<std::mutex> lock(mutex);
        stats.PathsA += r.PathsA;
        stats.PathsF += r.PathsF;
        stats.Vertices += r.Vertices;
        stats.CellsAtPathLimit += r.AtLimit ? 1 : 0;
        ++done;
        if (settings.Progress)
        {
          settings.Progress(done, cells.size());
        }
        const auto now = std::chrono::steady_clock::now();
        if (settings.Checkpoint && done < cells.size() &&
          std::chrono::duration<double>(now - lastCheckpoint).count() >= settings.CheckpointSeconds)
        {
          table.GenerationSeconds =
            earlierSeconds + std::chrono::duration<double>(now - start).count();
          settings.Checkpoint(table);
          lastCheckpoint = now;
        }
      }
    },
    settings.Threads);
  table.GenerationSeconds = earlierSeconds +
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (statistics)
  {
    *statistics = stats;
  }
  return table;
}

} // namespace avs
