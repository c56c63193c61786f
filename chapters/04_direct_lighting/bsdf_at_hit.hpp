// Room for one BSDF, made in place: a textured material's BSDF at one hit (with the texture's colours), on
// the caller's stack, so the material table stays shared and read-only between threads; and each of the
// table's own BSDFs. Any chapter's Bsdf of at most kBytes fits (a larger one does not compile).
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <utility>

#include "bsdf.hpp"

namespace rt {

class BsdfAtHit {
  public:
    static constexpr std::size_t kBytes = 64;

    BsdfAtHit() = default;
    BsdfAtHit(const BsdfAtHit&) = delete;
    BsdfAtHit& operator=(const BsdfAtHit&) = delete;
    ~BsdfAtHit() { clear(); }

    // Makes a B from `args` here, in place of what was here; valid until the next emplace.
    template <class B, class... Args>
    const B& emplace(Args&&... args) {
        static_assert(sizeof(B) <= kBytes && alignof(B) <= alignof(std::max_align_t), "a BSDF too large");
        clear();
        B* made = new (bytes_) B(std::forward<Args>(args)...);
        bsdf_ = made;
        return *made;
    }
    bool empty() const { return bsdf_ == nullptr; }

  private:
    void clear() {
        if (bsdf_) std::destroy_at(bsdf_);
        bsdf_ = nullptr;
    }

    alignas(std::max_align_t) std::byte bytes_[kBytes];
    Bsdf* bsdf_ = nullptr;
};

}  // namespace rt
