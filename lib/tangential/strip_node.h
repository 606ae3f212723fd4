// The traction at one node of a strip: what the steady march (lib/tangential/strip_march.h) carries
// from node to node and what Satran's state (lib/tangential/satran.h) holds between steps.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace contact {

struct StripNode {
  double tx = 0, ty = 0;  // Pa
  // direction of tau at the last slip (0 before any); read only where the node slips: the march takes a
  // stick node's direction afresh where its material starts to slip, so a stick node's is not kept up to date
  double ex = 0, ey = 0;
  bool stick = true;
};

// The nodes of a grid of strips, one array per quantity (Satran's state: its shift step takes a strip's
// tractions a SIMD block at a time, and writes only what a stick node changes). Reading a node by index or
// by iteration gives a StripNode by value.
struct StripNodes {
  std::vector<double> tx, ty, ex, ey;
  std::vector<unsigned char> stick;  // 1: stick

  std::size_t size() const { return tx.size(); }
  StripNode operator[](std::size_t k) const { return {tx[k], ty[k], ex[k], ey[k], stick[k] != 0}; }
  void set(std::size_t k, const StripNode& n) {
    tx[k] = n.tx;
    ty[k] = n.ty;
    ex[k] = n.ex;
    ey[k] = n.ey;
    stick[k] = n.stick ? 1 : 0;
  }
  void assign(std::size_t n, const StripNode& v) {
    tx.assign(n, v.tx);
    ty.assign(n, v.ty);
    ex.assign(n, v.ex);
    ey.assign(n, v.ey);
    stick.assign(n, v.stick ? 1 : 0);
  }
  // nodes from .. from + count - 1 copied to to .. to + count - 1 (ranges apart)
  void copy(std::size_t from, std::size_t to, std::size_t count) {
    std::copy_n(tx.begin() + from, count, tx.begin() + to);
    std::copy_n(ty.begin() + from, count, ty.begin() + to);
    std::copy_n(ex.begin() + from, count, ex.begin() + to);
    std::copy_n(ey.begin() + from, count, ey.begin() + to);
    std::copy_n(stick.begin() + from, count, stick.begin() + to);
  }

  class const_iterator {
   public:
    const_iterator(const StripNodes* s, std::size_t k) : s_(s), k_(k) {}
    StripNode operator*() const { return (*s_)[k_]; }
    const_iterator& operator++() {
      ++k_;
      return *this;
    }
    bool operator==(const const_iterator& o) const { return k_ == o.k_; }
    bool operator!=(const const_iterator& o) const { return k_ != o.k_; }

   private:
    const StripNodes* s_;
    std::size_t k_;
  };
  const_iterator begin() const { return {this, 0}; }
  const_iterator end() const { return {this, size()}; }
};

}  // namespace contact
