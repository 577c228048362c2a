// Back-solve bench (issue 30, the whole run's scaling; docs/measurements.md#m-back-solve-ordering):
// one matrix the scene factorises, solved by several orderings and factorisations. The matrix is a
// binary CSC file (long n, long nnz, int outer[n + 1], int inner[nnz], double value[nnz]; both
// triangles), written by a line added for the purpose at the top of SpdFactor::factorize
// (fwrite of a.rows(), a.nonZeros() and the three arrays of the compressed matrix) during a short
// run of the scene (-stopafter 1); it is not part of the plugin. Methods:
//   eigen-amd     Eigen's SimplicialLDLT, AMD ordering (SpdFactor's below 50 000 unknowns)
//   eigen-metis   the same with the METIS nested-dissection ordering CHOLMOD computes
//   eigen-nesdis  the same with CHOLMOD's own nested dissection (NESDIS, METIS's partitioner):
//                 SpdFactor's from 50 000 unknowns
//   chol-super-*  CHOLMOD's supernodal LL' (ordering: amd, metis, or CHOLMOD's default choice),
//                 the whole solve (cholmod_solve2, CHOLMOD_A) and its two halves (P, L | Lt, Pt:
//                 the forward/backward split the contact step uses)
// Prints nnz(L) of each and the median time of a forward + backward solve over interleaved rounds
// (each round times every method once, REPS solves each, so that a drift of the shared machine's
// speed falls on every method alike), and each method's largest relative difference to eigen-amd.
//   g++ -O3 -DNDEBUG -std=c++17 -I/usr/include/eigen3 -I/usr/include/suitesparse
//       tools/bench/backsolve.cpp -o /tmp/backsolve -lcholmod
//   OPENBLAS_NUM_THREADS=1 /tmp/backsolve matrix.bin [rounds] [reps]
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <cholmod.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

static SparseMatrix load(const char* path) {
  std::FILE* f = std::fopen(path, "rb");
  if (!f) { std::perror(path); std::exit(1); }
  long n = 0, nz = 0;
  if (std::fread(&n, sizeof n, 1, f) != 1 || std::fread(&nz, sizeof nz, 1, f) != 1) std::exit(1);
  std::vector<int> outer(n + 1), inner(nz);
  std::vector<double> value(nz);
  if (std::fread(outer.data(), sizeof(int), n + 1, f) != (size_t)(n + 1) ||
      std::fread(inner.data(), sizeof(int), nz, f) != (size_t)nz ||
      std::fread(value.data(), sizeof(double), nz, f) != (size_t)nz) std::exit(1);
  std::fclose(f);
  SparseMatrix a = Eigen::Map<const SparseMatrix>(n, n, nz, outer.data(), inner.data(), value.data());
  return a;
}

// A given permutation as an Eigen ordering (Eigen's ordering returns P^-1: its k-th index is the
// row of A that becomes row k, CHOLMOD's Perm[k]).
struct GivenOrdering {
  static std::vector<int> perm;
  template <class M>
  void operator()(const M&, Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>& pinv) {
    pinv.resize((int)perm.size());
    for (size_t k = 0; k < perm.size(); ++k) pinv.indices()[k] = perm[k];
  }
};
std::vector<int> GivenOrdering::perm;

struct Chol {
  cholmod_common c;
  cholmod_factor* L = nullptr;
  cholmod_sparse* A = nullptr;
  cholmod_dense *X = nullptr, *Y = nullptr, *E = nullptr, *B = nullptr, *Z = nullptr;
  std::string name;
  Chol(const SparseMatrix& a, int ordering, bool supernodal, const char* nm) : name(nm) {
    cholmod_start(&c);
    c.supernodal = supernodal ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
    if (ordering >= 0) {
      c.nmethods = 1;
      c.method[0].ordering = ordering;
      c.postorder = 1;
    }
    const SparseMatrix lower = a.triangularView<Eigen::Lower>();
    A = cholmod_allocate_sparse(a.rows(), a.cols(), lower.nonZeros(), 1, 1, -1, CHOLMOD_REAL, &c);
    std::copy(lower.outerIndexPtr(), lower.outerIndexPtr() + a.cols() + 1, (int*)A->p);
    std::copy(lower.innerIndexPtr(), lower.innerIndexPtr() + lower.nonZeros(), (int*)A->i);
    std::copy(lower.valuePtr(), lower.valuePtr() + lower.nonZeros(), (double*)A->x);
    L = cholmod_analyze(A, &c);
    cholmod_factorize(A, L, &c);
    if (c.status != CHOLMOD_OK) { std::fprintf(stderr, "%s: status %d\n", nm, c.status); std::exit(1); }
    B = cholmod_allocate_dense(a.rows(), 1, a.rows(), CHOLMOD_REAL, &c);
  }
  double lnz() const {
    return c.lnz;  // the factor's nonzeros (CHOLMOD's count, diagonal included)
  }
  std::vector<int> perm() const { return std::vector<int>((int*)L->Perm, (int*)L->Perm + L->n); }
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
    std::copy(b.data(), b.data() + b.size(), (double*)B->x);
    cholmod_solve2(CHOLMOD_A, L, B, nullptr, &X, nullptr, &Y, &E, &c);
    std::copy((double*)X->x, (double*)X->x + b.size(), x.data());
  }
  // the forward / backward halves: z = L^-1 P b, x = P' L^-T z
  void solve_split(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
    std::copy(b.data(), b.data() + b.size(), (double*)B->x);
    cholmod_solve2(CHOLMOD_P, L, B, nullptr, &X, nullptr, &Y, &E, &c);
    cholmod_solve2(CHOLMOD_L, L, X, nullptr, &Z, nullptr, &Y, &E, &c);
    cholmod_solve2(CHOLMOD_Lt, L, Z, nullptr, &X, nullptr, &Y, &E, &c);
    cholmod_solve2(CHOLMOD_Pt, L, X, nullptr, &Z, nullptr, &Y, &E, &c);
    std::copy((double*)Z->x, (double*)Z->x + b.size(), x.data());
  }
};

int main(int argc, char** argv) {
  if (argc < 2) { std::fprintf(stderr, "usage: backsolve matrix.bin [rounds] [reps]\n"); return 2; }
  const SparseMatrix a = load(argv[1]);
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 7, reps = argc > 3 ? std::atoi(argv[3]) : 10;
  const int n = (int)a.rows();
  std::printf("%s: n %d, nnz(A) %ld\n", argv[1], n, (long)a.nonZeros());

  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> amd;
  amd.compute(a);
  Chol sup_amd(a, CHOLMOD_AMD, true, "chol-super-amd"), sup_metis(a, CHOLMOD_METIS, true, "chol-super-metis"),
      sup_default(a, -1, true, "chol-super-default");
  GivenOrdering::perm = sup_metis.perm();
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, GivenOrdering> emetis, enesdis;
  emetis.compute(a);
  {
    Chol nesdis(a, CHOLMOD_NESDIS, false, "chol-nesdis");
    GivenOrdering::perm = nesdis.perm();
  }
  enesdis.compute(a);
  // nnz(L) with the diagonal, as CHOLMOD counts
  std::printf("nnz(L): eigen-nesdis %ld, ", (long)enesdis.matrixL().nestedExpression().nonZeros() + n);
  std::printf("eigen-amd %ld, eigen-metis %ld, chol-super-amd %.0f, chol-super-metis %.0f, chol-super-default %.0f (ordering %d)\n",
              (long)amd.matrixL().nestedExpression().nonZeros() + n, (long)emetis.matrixL().nestedExpression().nonZeros() + n,
              sup_amd.lnz(), sup_metis.lnz(), sup_default.lnz(), sup_default.L->ordering);

  std::mt19937 gen(1);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd b(n), ref(n), x(n);
  for (int i = 0; i < n; ++i) b[i] = u(gen);
  ref = amd.solve(b);
  struct Method { std::string name; std::function<void()> run; std::vector<double> ms; double diff = 0; };
  std::vector<Method> methods = {
      {"eigen-amd", [&] { x = amd.solve(b); }},
      {"eigen-metis", [&] { x = emetis.solve(b); }},
      {"eigen-nesdis", [&] { x = enesdis.solve(b); }},
      {"chol-super-amd", [&] { sup_amd.solve(b, x); }},
      {"chol-super-amd-split", [&] { sup_amd.solve_split(b, x); }},
      {"chol-super-metis", [&] { sup_metis.solve(b, x); }},
      {"chol-super-metis-split", [&] { sup_metis.solve_split(b, x); }},
      {"chol-super-default", [&] { sup_default.solve(b, x); }},
  };
  for (int r = 0; r < rounds; ++r)
    for (auto& m : methods) {
      const auto t0 = std::chrono::steady_clock::now();
      for (int k = 0; k < reps; ++k) m.run();
      const auto t1 = std::chrono::steady_clock::now();
      m.ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count() / reps);
      m.diff = std::max(m.diff, (x - ref).norm() / ref.norm());
    }
  double base = 0;
  for (auto& m : methods) {
    std::sort(m.ms.begin(), m.ms.end());
    const double med = m.ms[m.ms.size() / 2];
    if (m.name == "eigen-amd") base = med;
    std::printf("  %-24s median %8.3f ms  (min %8.3f, max %8.3f)  ratio to eigen-amd %.3f  rel diff %.1e\n",
                m.name.c_str(), med, m.ms.front(), m.ms.back(), med / base, m.diff);
  }
  return 0;
}
