(* The shadow feeler and POV-Ray's shadow cache (§4). *)

open Compiled
open Context

let f32 = Precision.f32

type filtered = { r : float; g : float; b : float; filter : float }

(* The robust mode's shadow segment from [o] to the light at [lp]: its direction and length. *)
let aim (lp : Vec.t) (o : Vec.t) =
  let v = Vec.sub lp o in
  let len = Vec.length v in
  (Vec.scale (1. /. len) v, len)

(* How far short of the light at [lp] a robust shadow segment of length [remaining] from near [p]
   stops counting hits. *)
let robust_margin ~shift (p : Vec.t) (lp : Vec.t) remaining = (1e-9 *. remaining) +. Robust.error_bound ~shift p lp remaining

(* ComputeShadowTexture for a texture at the point [q] of a shadow ray's crossing: the product of
   its layers' filter colours (each times the interior's faked caustics, [caustic], when it has
   them), then what the shadow ray met along the [t] it travelled inside [interiors] (the
   interior's fade, Segment.through), as an rgb with filter 1; a patterned texture's entries
   blended in all four channels (ComputeOneTextureColour). [warps]: the patterned textures
   around, the outermost first, whose spaces bend the normals. *)
let rec filter obj ~hit ~uv ~caustic ~interiors t (tex : texture) (q : Vec.t) warps : filtered =
  match tex with
  | Uv_mapped u -> filter obj ~hit ~uv ~caustic ~interiors t u.uinner (uv ()) (warps @ [ u.uwarps ])
  | Cutaway -> { r = 0.; g = 0.; b = 0.; filter = 0. } (* never inside another texture *)
  | Chosen c ->
      let tq = c.cwarp q in
      filter obj ~hit ~uv ~caustic ~interiors t c.textures.(c.choose tq) tq (warps @ [ c.cwarps ])
  | Plain s -> filter_layers obj ~hit ~caustic ~interiors t [| s |] q warps
  | Layered ls -> filter_layers obj ~hit ~caustic ~interiors t ls q warps
  | Blended b ->
      let tq = b.warp q in
      let warps = warps @ [ b.nwarps ] in
      if b.average then begin
        let r = ref 0. and g = ref 0. and bl = ref 0. and fl = ref 0. and total = ref 0. in
        Array.iteri
          (fun i e ->
            let c = filter obj ~hit ~uv ~caustic ~interiors t e tq warps in
            let v = b.values.(i) in
            r := f32 (!r +. f32 (c.r *. v));
            g := f32 (!g +. f32 (c.g *. v));
            bl := f32 (!bl +. f32 (c.b *. v));
            fl := f32 (!fl +. f32 (c.filter *. v));
            total := f32 (!total +. v))
          b.entries;
        let k = !total in
        { r = f32 (!r /. k); g = f32 (!g /. k); b = f32 (!bl /. k); filter = f32 (!fl /. k) }
      end
      else
        let v = b.value Patterns.no_hit tq in
        let prev, cur = Surfaces.around b.values v in
        let c1 = filter obj ~hit ~uv ~caustic ~interiors t b.entries.(cur) tq warps in
        if prev = cur then c1
        else
          let c2 = filter obj ~hit ~uv ~caustic ~interiors t b.entries.(prev) tq warps in
          let v1 = (v -. b.values.(prev)) /. (b.values.(cur) -. b.values.(prev)) in
          let v2 = 1. -. v1 in
          let mix x y = f32 (f32 (v1 *. x) +. f32 (v2 *. y)) in
          { r = mix c1.r c2.r; g = mix c1.g c2.g; b = mix c1.b c2.b; filter = mix c1.filter c2.filter }

and filter_layers obj ~hit ~caustic ~interiors t ls q warps =
  let c =
    Array.fold_left
      (fun (c : Rgb.t) (s : surface) ->
        let f = match s.paint with Fixed -> s.filcol | Varying at -> (at (hit s) q).filcol in
        let c = Rgb.make (f32 (c.r *. f.r)) (f32 (c.g *. f.g)) (f32 (c.b *. f.b)) in
        match caustic with
        | None -> c
        | Some k ->
            let k = k s q warps in
            Rgb.make (f32 (c.r *. k)) (f32 (c.g *. k)) (f32 (c.b *. k)))
      Rgb.white ls
  in
  let c = Segment.through Shadow obj interiors t c in
  { r = c.r; g = c.g; b = c.b; filter = 1. }

(* Faked caustics (ComputeShadowTexture): a layer lets through 1 + |N·L|^caustics times more,
   N the layer's normal at the crossing [q] (the shape's, turned against the shadow ray [l], bent by
   the layer's normal pattern in the space of the patterned textures around it) *)
let caustic ctx (obj : obj) part (q : Vec.t) (l : Vec.t) =
  let sc = ctx.scene in
  let raw = Shape.normal ctx.shapes obj part q in
  let raw = if Vec.dot raw l > 0. then Vec.neg raw else raw in
  fun (s : surface) (p : Vec.t) warps ->
    let n =
      match s.bump with
      | Smooth -> raw
      | Bumpy nm ->
          let uv = if s.needs_uv then Shape.uv obj part ctx.crossing q else Vec.zero in
          let wn = List.fold_left (fun v ws -> Normals.warp_normal ws ~keep_scale:false v) raw warps in
          let pn = Normals.perturb ~facets:ctx.facets sc.noise_generator nm p { Patterns.normal = raw; dir = l; uv } wn in
          List.fold_right (fun ws v -> Normals.unwarp_normal ws ~keep_scale:false v) warps (Normals.layer_normal nm pn)
    in
    1.0 +. Float.pow (Float.abs (Vec.dot n l)) obj.interior.caustics

(* Whether a shadow ray along [l] meets the surface of [obj] at [q] from inside (its normal,
   inverse counted, along the ray): it then sees the interior texture. *)
let inside_hit ctx (obj : obj) part q l =
  let dn = Vec.dot (Shape.normal ctx.shapes obj part q) l in
  if obj.inverted then dn < 0. else dn > 0.

(* ComputeShadowColour for any texture but a plain one without uv_mapping or caustics: the filter
   colour at the crossing [q], [t] along the shadow ray [l] from its last origin. *)
let textured ctx (obj : obj) part (q : Vec.t) (l : Vec.t) t interiors (tex : texture) : Rgb.t =
  let sc = ctx.scene in
  let hit (s : surface) = if s.needs_uv then { Patterns.no_hit with uv = Shape.uv obj part ctx.crossing q } else Patterns.no_hit in
  let caustic = if obj.interior.caustics = 0. then None else Some (caustic ctx obj part q l) in
  let uv () = Shape.uv obj part ctx.crossing q in
  let q' = if obj.uv_mapped then uv () else q in
  match tex with
  | Cutaway ->
      (* the members' filters weighed; none found stops the light *)
      let c =
        List.fold_left
          (fun (acc : filtered) (w, tex) ->
            if w < sc.adc_bailout then acc
            else
              let c = filter obj ~hit ~uv ~caustic ~interiors t tex q' [] in
              { r = f32 (acc.r +. f32 (w *. c.r)); g = f32 (acc.g +. f32 (w *. c.g)); b = f32 (acc.b +. f32 (w *. c.b)); filter = f32 (acc.filter +. f32 (w *. c.filter)) })
          { r = 0.; g = 0.; b = 0.; filter = 0. }
          (Surfaces.cutaway ctx.stack sc obj q)
      in
      if Float.abs c.filter < sc.adc_bailout then Rgb.black else Rgb.make (f32 (c.r *. c.filter)) (f32 (c.g *. c.filter)) (f32 (c.b *. c.filter))
  | Plain _ | Layered _ | Blended _ | Uv_mapped _ | Chosen _ ->
      (* the filter colour, weighed in by its filter channel; an object's uv_mapping evaluates its
         textures at the crossing's (u, v, 0) *)
      let c = filter obj ~hit ~uv ~caustic ~interiors t tex q' [] in
      Rgb.make (f32 (c.r *. c.filter)) (f32 (c.g *. c.filter)) (f32 (c.b *. c.filter))

(* The walk of a shadow ray from the hit [h] through non-opaque occluders towards the light: from
   [o] along [l] inside [interiors], the light [remaining] away (at [light] in the robust mode),
   [lc] the light's colour left; [cache]: the shadow-cache slot an opaque blocker of the first
   segment fills, −1 on the others. *)
let rec walk ctx (h : Hit.t) ~cache ~light (o : Vec.t) (l : Vec.t) interiors remaining (lc : Rgb.t) =
  let sc = ctx.scene in
  let lo = if ctx.robust then 0. else Precision.shadow_tolerance in
  let f = Nearest.search ctx Shadow sc.occluders o l lo remaining in
  let t = Nearest.depth f in
  if not (Nearest.hit f) || t >= remaining -. (if ctx.robust then robust_margin ~shift:ctx.scene.shift h.point light remaining else Precision.shadow_tolerance) then lc
  else
    let obj = sc.objects.(Nearest.id f) in
    if obj.opaque then begin
      (* the cache holds POV-Ray's Intersection.Csg (the outermost intersection, merge or
         clipped union around the member), else the primitive, and a CSG only when its own
         texture is opaque: POV-Ray tests the OPAQUE flag of that object *)
      if cache >= 0 && not sc.objects.(obj.cache).clear then ctx.shadow_cache.(cache) <- obj.cache;
      Rgb.black
    end
    else
      let part = Nearest.part f in
      (* the crossing, as the shape gives it (a poly's comes back from its own space, a julia
         fractal's is its march's); what the search kept of it ([ctx.crossing]) is read before
         the walk goes on *)
      let q = Shape.hit_point ctx.shapes obj ctx.crossing o t l in
      let tex = if obj.inner_tex = None then Surfaces.at obj part else Surfaces.seen obj part ~inside:(inside_hit ctx obj part q l) in
      let f =
        match tex with
        | Plain sf when (not obj.uv_mapped) && obj.interior.caustics = 0. ->
            (* §4, §17.8: a patterned pigment is evaluated where the shadow ray crosses it; a
               uv-mapped one at the crossing's UV coordinates *)
            let f =
              match sf.paint with
              | Fixed -> sf.filcol
              | Varying at ->
                  (at (if sf.needs_uv then { Patterns.no_hit with uv = Shape.uv obj part ctx.crossing q } else Patterns.no_hit) q).filcol
            in
            Segment.through Shadow obj interiors t f
        | Plain _ | Layered _ | Blended _ | Uv_mapped _ | Chosen _ | Cutaway -> textured ctx obj part q l t interiors tex
      in
      let lc = Rgb.make (f32 (lc.r *. f.r)) (f32 (lc.g *. f.g)) (f32 (lc.b *. f.b)) in
      let interiors = if List.mem obj.iid interiors then Optics.remove obj.iid interiors else obj.iid :: interiors in
      if not ctx.robust then walk ctx h ~cache:(-1) ~light q l interiors (remaining -. t) lc
      else
        let q = Shape.refine obj q in
        let next = Robust.origin ctx q (Shape.geometric_normal ctx.shapes obj part q) (Robust.error_bound ~shift:ctx.scene.shift o q obj.mag) l in
        let l, remaining = aim light next in
        walk ctx h ~cache:(-1) ~light next l interiors remaining lc

let feeler ctx (h : Hit.t) ~slot (smp : Light.sample) (lc : Rgb.t) : Rgb.t =
  let sc = ctx.scene and p = h.point and l = Light.direction smp and dist = smp.dist in
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
        let o = Hit.origin ctx h l in
        let l, dist = if ctx.robust then aim lp o else (l, dist) in
        (* a shadow test for a camera ray's hit tries the blocker cached for those, or else the
           one cached for the deeper levels (Trace::TracePointLightShadowRay, where the shadow
           ray's own trace level is 2) *)
        let cached =
          let c = ctx.shadow_cache.(slot) in
          if c < 0 && slot land 1 = 0 then ctx.shadow_cache.(slot + 1) else c
        in
        let in_cache =
          cached >= 0
          &&
          let shape = sc.objects.(cached).shape in
          (if ctx.robust then Nearest.shape_depth ctx Shadow shape o l lo < dist -. robust_margin ~shift:ctx.scene.shift p lp dist
           else Nearest.cached_depth ctx Shadow shape p l Precision.min_isect_depth dist < dist)
          (* a cached CSG shadows only if the member hit is opaque *)
          && ((not (Csg.is_csg shape)) || sc.objects.(ctx.shapes.leaf).opaque)
        in
        if in_cache then Rgb.black else walk ctx h ~cache:slot ~light:lp o l h.ray.interiors dist lc

