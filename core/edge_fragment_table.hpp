// The edge-fragment table EF in both organisations of the paper: a sorted table searched by
// binary search, and an open-addressing hash table. [MK89 §3.3]
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
  explicit SortedEdgeTable(std::size_t /*capacity*/) {}

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

// [MK89 §3.3, second method] Linear open addressing keyed by the fragment's first vertex.
// The entries live in one array in insertion order; a slot holds an entry's index + 1
// (0 = empty), so the table costs 4 bytes per slot at load factor at most 1/2. Deletion
// clears `alive` and leaves the slot occupied, so probe sequences stay intact.
class HashEdgeTable {
 public:
  explicit HashEdgeTable(std::size_t capacity) {
    std::size_t size = 16;
    while (size < 2 * capacity + 2) size *= 2;
    slots_.assign(size, 0);
    mask_ = size - 1;
    entries_.reserve(capacity);
  }

  void insert_batch(const std::vector<EfEntry>& batch, bool regular) {
    for (const auto& e : batch) insert(e, regular);
  }

  // InsertEF of one fragment; batches make no difference to a hash table.
  void insert(EfEntry e, bool regular) {
    e.alive = true;
    if (find(e.from, e.to)) return;
    if (regular) {
      if (EfEntry* opp = find(e.to, e.from)) {
        opp->alive = false;
        return;
      }
    }
    std::size_t i = hash(e.from);
    while (slots_[i] != 0) i = (i + 1) & mask_;
    entries_.push_back(e);
    slots_[i] = static_cast<std::uint32_t>(entries_.size());
  }

  template <class F>
  void for_each_from(int v, F&& f) {
    for (std::size_t i = hash(v); slots_[i] != 0; i = (i + 1) & mask_) {
      EfEntry& en = entries_[slots_[i] - 1];
      if (en.from == v && en.alive) f(en);
    }
  }
  template <class F>
  void for_each(F&& f) {
    for (EfEntry& en : entries_) {
      if (en.alive) f(en);
    }
  }

 private:
  std::size_t hash(int v) const {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(v)) * 0x9E3779B97F4A7C15ULL >> 17) & mask_;
  }
  EfEntry* find(int from, int to) {
    for (std::size_t i = hash(from); slots_[i] != 0; i = (i + 1) & mask_) {
      EfEntry& en = entries_[slots_[i] - 1];
      if (en.from == from && en.to == to && en.alive) return &en;
    }
    return nullptr;
  }
  std::vector<std::uint32_t> slots_;
  std::vector<EfEntry> entries_;  // insertion order, for a deterministic walk
  std::size_t mask_ = 0;
};

}  // namespace mk
