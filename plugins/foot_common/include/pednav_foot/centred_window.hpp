// A time-centred sliding window over a stream of samples, O(1) amortised per
// sample: each sample enters and leaves the running accumulator once. The
// window of the sample at t_c holds every sample with |t - t_c| <= half_ns; its
// result is ready once a sample with t >= t_c + half_ns has arrived, so the
// stage's look-ahead is exactly half_ns. Storage is a ring allocated once.
#pragma once

#include <cstdint>
#include <memory>

namespace pednav::foot {

// Acc provides: add(const Elem&), remove(const Elem&), reset(), and
// Elem is any struct with an int64_t t_ns member.
template <class Elem, class Acc>
class CentredWindow {
public:
    CentredWindow(int64_t half_ns, size_t min_capacity) : half_ns_(half_ns) {
        size_t cap = 16;
        while (cap < min_capacity) cap <<= 1;
        ring_.reset(new Elem[cap]());
        cap_ = cap;
        mask_ = cap - 1;
    }

    int64_t half_ns() const { return half_ns_; }
    Acc& acc() { return acc_; }

    // Appends a sample; calls out(centre_elem, acc) for every centre whose
    // window is complete, in time order.
    template <class Out>
    void push(const Elem& e, Out&& out) {
        if (n_ - lo_ >= cap_) make_room(out);
        ring_[n_ & mask_] = e;
        ++n_;
        const int64_t t_new = e.t_ns;
        while (c_ < n_ && t_new >= at(c_).t_ns + half_ns_) emit_centre(out);
    }

    // Finishes every centre whose window ends at or before `watermark_ns`:
    // the caller guarantees that every sample up to the watermark has been
    // pushed (a downstream stage uses the raw input time minus the upstream
    // look-ahead, so cascaded stages add no sampling delay to the latency).
    template <class Out>
    void advance(int64_t watermark_ns, Out&& out) {
        while (c_ < n_ && at(c_).t_ns + half_ns_ <= watermark_ns) emit_centre(out);
    }

    // End of stream: finish every pending centre with a truncated window.
    template <class Out>
    void flush(Out&& out) {
        while (c_ < n_) emit_centre(out);
    }

private:
    const Elem& at(uint64_t i) const { return ring_[i & mask_]; }

    // Ring full (input faster than the capacity assumed): shrink the window
    // from the left, finishing the oldest centre if needed.
    template <class Out>
    void make_room(Out& out) {
        while (n_ - lo_ >= cap_) {
            if (lo_ < c_ && lo_ < hi_) {
                acc_.remove(at(lo_));
                ++lo_;
            } else {
                emit_centre(out);
            }
        }
    }

    // The indices are kept in locals in the loops: the accumulator's stores
    // could otherwise alias them and force reloads.
    template <class Out>
    void emit_centre(Out& out) {
        const Elem* ring = ring_.get();
        const uint64_t mask = mask_, n = n_, c = c_;
        const Elem& centre = ring[c & mask];
        const int64_t t_hi = centre.t_ns + half_ns_;
        uint64_t hi = hi_;
        while (hi < n && ring[hi & mask].t_ns <= t_hi) {
            acc_.add(ring[hi & mask]);
            ++hi;
        }
        hi_ = hi;
        const int64_t t_lo = centre.t_ns - half_ns_;
        uint64_t lo = lo_;
        while (lo < c && ring[lo & mask].t_ns < t_lo) {
            acc_.remove(ring[lo & mask]);
            ++lo;
        }
        lo_ = lo;
        if (++since_rebuild_ >= 8192) rebuild();
        out(centre, acc_);
        c_ = c + 1;
    }

    // Recomputes the accumulator from the window contents, bounding the
    // round-off that add/remove pairs accumulate over a long stream.
    void rebuild() {
        since_rebuild_ = 0;
        acc_.reset();
        for (uint64_t i = lo_; i < hi_; ++i) acc_.add(at(i));
    }

    int64_t half_ns_;
    std::unique_ptr<Elem[]> ring_;
    uint64_t cap_ = 0;
    uint64_t mask_ = 0;
    uint64_t n_ = 0;   // samples pushed
    uint64_t c_ = 0;   // next centre to finish
    uint64_t lo_ = 0;  // first sample inside the accumulator
    uint64_t hi_ = 0;  // one past the last sample inside the accumulator
    uint32_t since_rebuild_ = 0;
    Acc acc_;
};

}  // namespace pednav::foot
