// The edge-fragment table EF in both organisations of the paper: a sorted table searched by
// binary search, and a hash table (buckets by vertex id). [MK89 §3.3]
// Preconditions: vertices are keyed by identity (vertex id), not by coordinates: an
// exact-arithmetic deviation recorded in paper-notes.md.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

#include "predicates/directions.hpp"

namespace mk {

enum class EfOrganisation : unsigned char { sorted, hash };

// A selected edge fragment: from -> to, travelling in direction `dir`.
struct EfEntry {
  int from = -1;
  int to = -1;
  Direction dir;
  bool alive = false;
};

// [MK89 §3.3, first method] Fragments appended in batches (A's, then B's); each batch is
// checked against the sorted table by binary search, then the table is sorted again.
class SortedEdgeTable {
 public:
  // InsertEF over a batch: a fragment already present is not inserted again; in regular
  // mode a fragment whose opposite is present deletes it and is not inserted.
  void insert_batch(std::vector<EfEntry> batch, bool regular) {
    for (auto& e : batch) {
      e.alive = true;
      if (EfEntry* same = find_sorted(e.from, e.to)) {
        (void)same;
        continue;
      }
      if (regular) {
        if (EfEntry* opp = find_sorted(e.to, e.from)) {
          opp->alive = false;
          continue;
        }
      }
      pending_.push_back(e);
    }
    // Within the batch, the same rules (a batch is inserted one fragment at a time).
    std::sort(pending_.begin(), pending_.end(), by_key);
    std::vector<EfEntry> kept;
    kept.reserve(pending_.size());
    for (const auto& e : pending_) {
      if (!kept.empty() && kept.back().from == e.from && kept.back().to == e.to) continue;
      kept.push_back(e);
    }
    if (regular) {
      for (auto& e : kept) {
        if (!e.alive) continue;
        auto it = std::lower_bound(kept.begin(), kept.end(), EfEntry{e.to, e.from, {}, false}, by_key);
        if (it != kept.end() && it->from == e.to && it->to == e.from && it->alive) {
          it->alive = false;
          e.alive = false;
        }
      }
    }
    pending_.clear();
    for (const auto& e : kept) {
      if (e.alive) table_.push_back(e);
    }
    std::sort(table_.begin(), table_.end(), by_key);
  }

  template <class F>
  void for_each_from(int v, F&& f) {
    auto it = std::lower_bound(table_.begin(), table_.end(), EfEntry{v, -1, {}, false}, by_key);
    for (; it != table_.end() && it->from == v; ++it) {
      if (it->alive) f(*it);
    }
  }
  template <class F>
  void for_each(F&& f) {
    for (auto& e : table_) {
      if (e.alive) f(e);
    }
  }


 private:
  static bool by_key(const EfEntry& a, const EfEntry& b) {
    return a.from != b.from ? a.from < b.from : a.to < b.to;
  }
  EfEntry* find_sorted(int from, int to) {
    auto it = std::lower_bound(table_.begin(), table_.end(), EfEntry{from, to, {}, false}, by_key);
    if (it != table_.end() && it->from == from && it->to == to && it->alive) return &*it;
    return nullptr;
  }
  std::vector<EfEntry> table_;
  std::vector<EfEntry> pending_;
};

// [MK89 §3.3, second method] Hashing on the fragment's first vertex. Vertex ids are dense
// (0 .. num_vertices - 1), so the hash function is the identity into num_vertices buckets,
// each a chain of entries in insertion order: no collisions between vertices, and the
// buckets of the consecutive vertices of a walk (near ids, as ids follow lexicographic
// order) lie near each other in memory. 4 bytes per vertex and 8 per entry beside the
// entries. Deletion clears `alive` and leaves the entry in its chain.
// An entry may also stand for a run of consecutive fragments of one cycle whose inner
// vertices no other fragment meets (insert_run): the walk of step 6 goes through such a
// vertex one way only, so the run is one entry from its first vertex to its last, with its
// inner vertices and the directions after the first kept beside the entries. A run never
// equals or opposes another entry (its inner vertices are its own), so the duplicate and
// opposite tests of single fragments pass over runs.
class HashEdgeTable {
 public:
  HashEdgeTable(std::size_t capacity, int num_vertices) : head_(static_cast<std::size_t>(num_vertices), -1) {
    entries_.reserve(capacity);
    next_.reserve(capacity);
    run_.reserve(capacity);
  }

  // InsertEF of one fragment; batches make no difference to a hash table. One walk along
  // e.from's chain both finds a copy of e and reaches the chain's end, where e is linked.
  void insert(EfEntry e, bool regular) {
    e.alive = true;
    int* link = nullptr;
    if (is_long(e.from)) {
      if (find(e.from, e.to) != nullptr) return;
      link = &next_[static_cast<std::size_t>(long_chains_.tail.at(e.from))];
    } else {
      int length = 0;
      for (link = &head_[static_cast<std::size_t>(e.from)]; *link >= 0; link = &next_[static_cast<std::size_t>(*link)]) {
        const EfEntry& en = entries_[static_cast<std::size_t>(*link)];
        if (en.to == e.to && en.alive && run_[static_cast<std::size_t>(*link)] < 0) return;
        ++length;
      }
      if (length >= kLongChain) {
        index_long_chain(e.from);
        link = &next_[static_cast<std::size_t>(long_chains_.tail.at(e.from))];
      }
    }
    if (regular) {
      if (EfEntry* opp = find(e.to, e.from)) {
        opp->alive = false;
        return;
      }
    }
    append(link, e, -1);
  }

  // Whether v's chain is long (kLongChain entries or more when an entry was last added):
  // such a chain is indexed by the entries' `to` as well, and step 6 orders it by angle.
  static constexpr int kLongChain = 32;
  bool is_long(int v) const {
    const auto w = static_cast<std::size_t>(v) / 64;
    return w < long_chains_.bits.size() && ((long_chains_.bits[w] >> (v % 64)) & 1) != 0;
  }

  // Room for `n` inner vertices of runs, each written once by set_inner before the run that
  // holds it is inserted (the pages are touched only as runs fill them).
  void make_inner_room(std::size_t n) {
    inner_ = std::make_unique_for_overwrite<int[]>(n);
    inner_dirs_ = std::make_unique_for_overwrite<InnerDirection[]>(n);
  }
  // Inner vertex k of some run: v, left along `leaving`.
  void set_inner(std::size_t k, int v, Direction leaving) {
    inner_[k] = v;
    inner_dirs_[k] = {leaving.from, leaving.to};
  }
  // A run of fragments from e.from to e.to (e.dir leaving e.from) through the inner vertices
  // begin .. begin + count - 1 (count >= 1), in order. Inserted as it is: a run has no copy
  // and no opposite.
  void insert_run(const EfEntry& e, std::size_t begin, std::size_t count) {
    int* link = &head_[static_cast<std::size_t>(e.from)];
    if (is_long(e.from)) {
      link = &next_[static_cast<std::size_t>(long_chains_.tail.at(e.from))];
    } else {
      int length = 0;
      for (; *link >= 0; link = &next_[static_cast<std::size_t>(*link)]) ++length;
      if (length >= kLongChain) {
        index_long_chain(e.from);
        link = &next_[static_cast<std::size_t>(long_chains_.tail.at(e.from))];
      }
    }
    runs_.push_back({begin, count});
    append(link, e, static_cast<int>(runs_.size()) - 1);
  }

  // An entry's inner vertices: {first, count} (count 0 for one fragment), for append_inner.
  std::pair<std::size_t, std::size_t> inner_range(const EfEntry& e) const {
    const int r = run_[static_cast<std::size_t>(&e - entries_.data())];
    return r < 0 ? std::pair<std::size_t, std::size_t>{0, 0} : runs_[static_cast<std::size_t>(r)];
  }
  std::size_t num_runs() const { return runs_.size(); }
  // Appends inner vertices [first, first + count) to `vertices` and their leaving directions
  // to `dirs`, in one copy each (step 6 moves runs of 10^5 vertices).
  void append_inner(std::size_t first, std::size_t count, std::vector<int>& vertices, std::vector<Direction>& dirs) const {
    vertices.insert(vertices.end(), inner_.get() + first, inner_.get() + first + count);
    const std::size_t at = dirs.size();
    dirs.resize(at + count);
    for (std::size_t k = 0; k < count; ++k) dirs[at + k] = {inner_dirs_[first + k].from, inner_dirs_[first + k].to};
  }

  // Entries in insertion order, dead ones included, for a walk made apart from the table.
  std::size_t size() const { return entries_.size(); }
  const EfEntry& entry(std::size_t i) const { return entries_[i]; }
  // The one live entry from v, or -1 when there are none or several.
  int only_from(int v) const {
    int only = -1;
    for (int i = head_[static_cast<std::size_t>(v)]; i >= 0; i = next_[static_cast<std::size_t>(i)]) {
      if (!entries_[static_cast<std::size_t>(i)].alive) continue;
      if (only >= 0) return -1;
      only = i;
    }
    return only;
  }

  template <class F>
  void for_each_from(int v, F&& f) {
    for (int i = head_[static_cast<std::size_t>(v)]; i >= 0; i = next_[static_cast<std::size_t>(i)]) {
      EfEntry& en = entries_[static_cast<std::size_t>(i)];
      if (en.alive) f(en);
    }
  }
  template <class F>
  void for_each(F&& f) {
    for (EfEntry& en : entries_) {
      if (en.alive) f(en);
    }
  }

 private:
  EfEntry* find(int from, int to) {
    if (is_long(from)) {
      const auto it = long_chains_.by_key.find(key(from, to));
      if (it == long_chains_.by_key.end()) return nullptr;
      EfEntry& en = entries_[static_cast<std::size_t>(it->second)];
      return en.alive ? &en : nullptr;
    }
    for (int i = head_[static_cast<std::size_t>(from)]; i >= 0; i = next_[static_cast<std::size_t>(i)]) {
      EfEntry& en = entries_[static_cast<std::size_t>(i)];
      if (en.to == to && en.alive && run_[static_cast<std::size_t>(i)] < 0) return &en;
    }
    return nullptr;
  }
  // Links e (run r, or -1) at `link`, the end of its vertex's chain.
  void append(int* link, const EfEntry& e, int r) {
    *link = static_cast<int>(entries_.size());
    // Made in place from e's fields: copying e whole would wait for the narrow stores that
    // just made it (GCC 12).
    EfEntry& made = entries_.emplace_back();  // in place, fields set (aggregates: no parenthesised init in clang 14)
    made.from = e.from;
    made.to = e.to;
    made.dir = e.dir;
    made.alive = true;
    next_.push_back(-1);
    run_.push_back(r);
    if (is_long(e.from)) {
      const int i = static_cast<int>(entries_.size()) - 1;
      long_chains_.tail[e.from] = i;
      if (r < 0) long_chains_.by_key[key(e.from, e.to)] = i;
    }
  }
  static std::uint64_t key(int from, int to) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(from)) << 32) | static_cast<std::uint32_t>(to);
  }
  // Marks v's chain long and indexes it: each (from, to) of a single fragment to its last
  // entry (an earlier one with the same key is dead: insert adds none beside a live one).
  void index_long_chain(int v) {
    if (long_chains_.bits.empty()) long_chains_.bits.assign(head_.size() / 64 + 1, 0);
    long_chains_.bits[static_cast<std::size_t>(v) / 64] |= std::uint64_t{1} << (v % 64);
    for (int i = head_[static_cast<std::size_t>(v)]; i >= 0; i = next_[static_cast<std::size_t>(i)]) {
      if (run_[static_cast<std::size_t>(i)] < 0) long_chains_.by_key[key(v, entries_[static_cast<std::size_t>(i)].to)] = i;
      long_chains_.tail[v] = i;
    }
  }
  std::vector<int> head_;         // per vertex: its first entry, or -1
  std::vector<int> next_;         // per entry: the next entry from the same vertex, or -1
  std::vector<EfEntry> entries_;  // insertion order, for a deterministic walk
  // A direction as stored for inner vertices: no initialisation, so that make_inner_room
  // touches no page.
  struct InnerDirection {
    int from, to;
  };
  // The long chains: a bit per vertex (allocated at the first), each one's last entry, and
  // their single fragments by (from, to).
  struct LongChains {
    std::vector<std::uint64_t> bits;
    std::unordered_map<int, int> tail;
    std::unordered_map<std::uint64_t, int> by_key;
  } long_chains_;
  std::vector<int> run_;  // per entry: its run, or -1 for one fragment
  std::vector<std::pair<std::size_t, std::size_t>> runs_;  // per run: its inner vertices (first, count)
  std::unique_ptr<int[]> inner_;                          // the runs' inner vertices
  std::unique_ptr<InnerDirection[]> inner_dirs_;          // the direction leaving each
};

}  // namespace mk
