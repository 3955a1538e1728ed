#pragma once
// Rays traced as Embree packets of the width the device runs natively, and
// how a callback tells which of the caller's rays a lane holds.
//
// Embree calls a user geometry back at the width it traces with, not the
// caller's: with AVX2 it splits a 16-ray packet into two of 8, with SSE into
// four of 4, and it may reorder rays (it sorts incoherent occlusion rays by
// octant). Lane i of a callback is therefore not lane i of the caller's
// packet. Every ray carries the caller's index for it in its `id` field
// (set_embree_ray), and a callback finds per-ray data by ray_index(), never
// by its lane number. Packets issued at the native width spare Embree the
// split and its copies.

#include <embree3/rtcore.h>

namespace hsb {

// 16 with AVX-512, 8 with AVX or AVX2, 4 with SSE: the widest packet the
// device traces without splitting it; 1 when it traces no packets.
int native_packet_width(RTCDevice device);

// The caller's index of the ray in lane i of a callback's packet of n.
inline unsigned ray_index(RTCRayN* rays, unsigned n, unsigned i) { return RTCRayN_id(rays, n, i); }

// Traces the rays whose bits are set in `rays` (ray i is bit i, i < 16)
// through `scene`, `width` lanes a packet (width is 1, 4, 8 or 16): ray i
// goes to lane i mod width of packet i / width, and a packet with no ray is
// skipped. set(packet, width, lane, index) fills `lane` with ray `index`,
// whose id must be `index`; get(packet, width, lane, index) reads its
// answer once the packet is traced. `Packet` is RTCRayHitN (intersect) or
// RTCRayN (occluded). Keeping a ray in the lane of its index, holes and
// all, lets a callback that is handed the whole packet use the caller's
// per-ray data in place (BlobGeometry's span query does).
template <class Set, class Get>
void intersect_rays(RTCScene scene, RTCIntersectContext* context, int width, unsigned rays, Set&& set, Get&& get);
template <class Set, class Get>
void occluded_rays(RTCScene scene, RTCIntersectContext* context, int width, unsigned rays, Set&& set, Get&& get);

// The mask of rays [0, count).
inline unsigned first_rays(int count) { return count >= 32 ? ~0u : (1u << count) - 1u; }

namespace detail {

// Both entry points: Storage holds a packet of any width (the 16-wide
// structure, used with a narrower stride), Trace issues one packet.
template <class Storage, class Single, class Packet, class Set, class Get, class Trace>
void trace_in_packets(int width, unsigned rays, Set&& set, Get&& get, Trace&& trace) {
  if (width == 1) {  // one ray at a time: no packet to clear
    for (unsigned rest = rays; rest; rest &= rest - 1) {
      const int i = __builtin_ctz(rest);
      Single ray;
      set(reinterpret_cast<Packet*>(&ray), 1u, 0u, i);
      trace(nullptr, &ray);
      get(reinterpret_cast<Packet*>(&ray), 1u, 0u, i);
    }
    return;
  }
  alignas(64) Storage storage{};  // idle lanes stay zero: finite, never traced
  alignas(64) int valid[16];
  auto* packet = reinterpret_cast<Packet*>(&storage);
  const unsigned lanes = (1u << width) - 1u;
  for (int first = 0; first < 16 && (rays >> first); first += width) {
    const unsigned here = (rays >> first) & lanes;
    if (!here) continue;
    for (int lane = 0; lane < width; ++lane) {
      valid[lane] = (here >> lane) & 1u ? -1 : 0;
      if (valid[lane]) set(packet, unsigned(width), unsigned(lane), first + lane);
    }
    trace(valid, &storage);
    for (int lane = 0; lane < width; ++lane)
      if (valid[lane]) get(packet, unsigned(width), unsigned(lane), first + lane);
  }
}

}  // namespace detail

template <class Set, class Get>
void intersect_rays(RTCScene scene, RTCIntersectContext* context, int width, unsigned rays, Set&& set, Get&& get) {
  detail::trace_in_packets<RTCRayHit16, RTCRayHit, RTCRayHitN>(width, rays, set, get, [&](const int* valid, void* p) {
    switch (width) {
      case 16: rtcIntersect16(valid, scene, context, static_cast<RTCRayHit16*>(p)); break;
      case 8: rtcIntersect8(valid, scene, context, static_cast<RTCRayHit8*>(p)); break;
      case 4: rtcIntersect4(valid, scene, context, static_cast<RTCRayHit4*>(p)); break;
      default: rtcIntersect1(scene, context, static_cast<RTCRayHit*>(p)); break;
    }
  });
}

template <class Set, class Get>
void occluded_rays(RTCScene scene, RTCIntersectContext* context, int width, unsigned rays, Set&& set, Get&& get) {
  detail::trace_in_packets<RTCRay16, RTCRay, RTCRayN>(width, rays, set, get, [&](const int* valid, void* p) {
    switch (width) {
      case 16: rtcOccluded16(valid, scene, context, static_cast<RTCRay16*>(p)); break;
      case 8: rtcOccluded8(valid, scene, context, static_cast<RTCRay8*>(p)); break;
      case 4: rtcOccluded4(valid, scene, context, static_cast<RTCRay4*>(p)); break;
      default: rtcOccluded1(scene, context, static_cast<RTCRay*>(p)); break;
    }
  });
}

}  // namespace hsb
