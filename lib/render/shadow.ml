(* The shadow feeler and POV-Ray's shadow cache (§4). *)

open Compiled
open Context

let f32 = Precision.f32

(* The robust mode's shadow segment from [o] to the light at [lp]: its direction and length. *)
let aim (lp : Vec.t) (o : Vec.t) =
  let v = Vec.sub lp o in
  let len = Vec.length v in
  (Vec.scale (1. /. len) v, len)

(* How far short of the light at [lp] a robust shadow segment of length [remaining] from near [p]
   stops counting hits. *)
let robust_margin (p : Vec.t) (lp : Vec.t) remaining = (1e-9 *. remaining) +. Robust.error_bound p lp remaining

(* The walk of a shadow ray from [o] along [l] towards the light at [lp], [remaining] from it,
   through non-opaque occluders; [first] on the first segment, whose opaque blocker is cached. *)
let rec walk ctx ~slot (p : Vec.t) (lp : Vec.t) lo first (o : Vec.t) (l : Vec.t) remaining interiors (lc : Rgb.t) =
  let sc = ctx.scene in
  let i = Nearest.search ctx sc.occluders o l lo remaining in
  let t = ctx.reach.depth in
  if i < 0 || t >= remaining -. (if ctx.robust then robust_margin p lp remaining else Precision.shadow_tolerance) then lc
  else
    let obj = sc.objects.(i) in
    if obj.opaque then begin
      (* the cache holds the top-level object (a CSG, not its member), and a CSG only when
         its own texture is opaque: POV-Ray tests the OPAQUE flag of Intersection.Csg *)
      if first && not sc.objects.(obj.top).surf.transparent then ctx.shadow_cache.(slot) <- obj.top;
      Rgb.black
    end
    else
      let part = ctx.found.part in
      let sf = Surfaces.at obj part in
      (* §4, §17.8: a patterned pigment is evaluated where the shadow ray crosses it *)
      let f =
        match sf.paint with
        | Fixed -> sf.filcol
        | Varying at ->
            let q = Vec.madd o t l in
            (* ComputeShadowColour: a uv-mapped pigment is evaluated at the crossing's UV coordinates *)
            (at (if sf.needs_uv then { Patterns.no_hit with uv = Shape.uv obj part q } else Patterns.no_hit) q).filcol
      in
      let f = if List.mem obj.iid interiors && obj.fade_power > 0. && Optics.fades obj then Optics.fade obj t f else f in
      let lc = Rgb.make (f32 (lc.r *. f.r)) (f32 (lc.g *. f.g)) (f32 (lc.b *. f.b)) in
      let interiors = if List.mem obj.iid interiors then Optics.remove obj.iid interiors else obj.iid :: interiors in
      let q = Vec.madd o t l in
      if not ctx.robust then walk ctx ~slot p lp lo false q l (remaining -. t) interiors lc
      else
        let q = Shape.refine obj q in
        let next = Robust.origin ctx q (Shape.geometric_normal obj part q) (Robust.error_bound o q obj.mag) l in
        let l, remaining = aim lp next in
        walk ctx ~slot p lp lo false next l remaining interiors lc

let feeler ctx ~slot (p : Vec.t) (ng : Vec.t) e (l : Vec.t) dist interiors (lc : Rgb.t) : Rgb.t =
  let sc = ctx.scene in
  ctx.stats.shadow_rays <- ctx.stats.shadow_rays + 1;
  (* a light at an infinite distance (a coordinate beyond the float range) has no direction: a
     filtered walk towards it would never end (a NaN ray from inside a box's slabs meets the box
     at 2e10 again and again) *)
  if not (Float.is_finite dist) then lc
  else
    match sc.shadow_mode with
    | No_occluders -> lc
    | Any_hit | Filtered ->
        (* POV-Ray: hits from 1e-3 to the light minus 1e-3, the ray going on from each crossing.
           The robust mode: every segment starts at a lifted origin and is aimed at the light anew,
           so the lift never shortens the way to the light; hits count up to the light minus a
           margin relative to the segment's length. *)
        let lp = if ctx.robust then Vec.madd p dist l else p in
        let lo = if ctx.robust then 0. else Precision.shadow_tolerance in
        let o = Robust.origin ctx p ng e l in
        let l, dist = if ctx.robust then aim lp o else (l, dist) in
        let cached = ctx.shadow_cache.(slot) in
        let in_cache =
          cached >= 0
          &&
          let shape = sc.objects.(cached).shape in
          (if ctx.robust then Shape.depth ctx.shapes shape o l lo < dist -. robust_margin p lp dist
           else Shape.depth ctx.shapes shape p l Precision.min_isect_depth < dist)
          (* a cached CSG shadows only if the member hit is opaque *)
          && ((not (Csg.is_csg shape)) || sc.objects.(ctx.shapes.leaf).opaque)
        in
        if in_cache then Rgb.black else walk ctx ~slot p lp lo true o l dist interiors lc
