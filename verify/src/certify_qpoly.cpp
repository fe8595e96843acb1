// Exact polynomial algebra for the tie proofs (certify_qpoly.hpp).
#include "gizmo/verify/certify_qpoly.hpp"

namespace gizmo::verify::detail {

void trim(QPoly& p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
}

QPoly product(const QPoly& a, const QPoly& b) {
  if (a.empty() || b.empty()) return {};
  QPoly r(a.size() + b.size() - 1, Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  trim(r);
  return r;
}

Rational valueAt(const QPoly& p, const Rational& x) {
  Rational r(0);
  for (std::size_t i = p.size(); i-- > 0;) r = r * x + p[i];
  return r;
}

namespace {

// a mod b (b not 0): the leading term of a is cancelled until a's degree falls below b's.
QPoly remainder(QPoly a, const QPoly& b) {
  while (a.size() >= b.size() && !a.empty()) {
    const Rational factor = a.back() / b.back();
    const std::size_t shift = a.size() - b.size();
    for (std::size_t i = 0; i + 1 < b.size(); ++i) a[shift + i] -= factor * b[i];
    a.pop_back();  // cancelled exactly
    trim(a);
  }
  return a;
}

QPoly derivative(const QPoly& p) {
  QPoly d;
  for (std::size_t i = 1; i < p.size(); ++i) d.push_back(p[i] * Rational(static_cast<long>(i)));
  trim(d);
  return d;
}

int signOf(const Rational& x) { return x < 0 ? -1 : (0 < x ? 1 : 0); }

}  // namespace

QPoly gcdOf(QPoly a, QPoly b) {
  trim(a);
  trim(b);
  while (!b.empty()) {
    QPoly r = remainder(a, b);
    a = std::move(b);
    b = std::move(r);
  }
  if (!a.empty()) {
    const Rational lead = a.back();
    for (Rational& c : a) c /= lead;
  }
  return a;
}

SturmChain::SturmChain(const QPoly& p) {
  QPoly a = p;
  trim(a);
  if (a.empty()) return;
  QPoly b = derivative(a);
  chain_.push_back(a);
  while (!b.empty()) {
    chain_.push_back(b);
    QPoly r = remainder(chain_[chain_.size() - 2], b);
    for (Rational& c : r) c = -c;
    b = std::move(r);
  }
}

int SturmChain::signChangesAt(const Rational& x) const {
  int changes = 0, last = 0;
  for (const QPoly& q : chain_) {
    const int s = signOf(valueAt(q, x));
    if (s == 0) continue;
    if (last != 0 && s != last) ++changes;
    last = s;
  }
  return changes;
}

int SturmChain::rootsIn(const Rational& a, const Rational& b) const { return signChangesAt(a) - signChangesAt(b); }

}  // namespace gizmo::verify::detail
