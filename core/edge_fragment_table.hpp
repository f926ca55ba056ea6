// The edge-fragment table EF in both organisations of the paper: a sorted table searched by
// binary search, and a hash table (buckets by vertex id). [MK89 §3.3]
// Preconditions: vertices are keyed by identity (vertex id), not by coordinates: an
// exact-arithmetic deviation recorded in paper-notes.md.
#pragma once

#include <algorithm>
#include <cstdint>
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
// order) lie near each other in memory. 4 bytes per vertex and 4 per entry beside the
// entries. Deletion clears `alive` and leaves the entry in its chain.
class HashEdgeTable {
 public:
  HashEdgeTable(std::size_t capacity, int num_vertices) : head_(static_cast<std::size_t>(num_vertices), -1) {
    entries_.reserve(capacity);
    next_.reserve(capacity);
  }

  // InsertEF of one fragment; batches make no difference to a hash table. One walk along
  // e.from's chain both finds a copy of e and reaches the chain's end, where e is linked.
  void insert(EfEntry e, bool regular) {
    e.alive = true;
    int* link = &head_[static_cast<std::size_t>(e.from)];
    for (; *link >= 0; link = &next_[static_cast<std::size_t>(*link)]) {
      const EfEntry& en = entries_[static_cast<std::size_t>(*link)];
      if (en.to == e.to && en.alive) return;
    }
    if (regular) {
      if (EfEntry* opp = find(e.to, e.from)) {
        opp->alive = false;
        return;
      }
    }
    *link = static_cast<int>(entries_.size());
    // Made in place from e's fields: copying e whole would wait for the narrow stores that
    // just made it (GCC 12).
    EfEntry& made = entries_.emplace_back();  // in place, fields set (aggregates: no parenthesised init in clang 14)
    made.from = e.from;
    made.to = e.to;
    made.dir = e.dir;
    made.alive = true;
    next_.push_back(-1);
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
    for (int i = head_[static_cast<std::size_t>(from)]; i >= 0; i = next_[static_cast<std::size_t>(i)]) {
      EfEntry& en = entries_[static_cast<std::size_t>(i)];
      if (en.to == to && en.alive) return &en;
    }
    return nullptr;
  }
  std::vector<int> head_;         // per vertex: its first entry, or -1
  std::vector<int> next_;         // per entry: the next entry from the same vertex, or -1
  std::vector<EfEntry> entries_;  // insertion order, for a deterministic walk
};

}  // namespace mk
