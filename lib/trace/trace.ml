(* The recursive Whitted tracer (docs/lecture.md; docs/povray-rules.md §2–§7). The colour seen
   along a ray is a function of the compiled scene and the ray, found in the lecture's steps:

     trace_ray    termination (the trace level, the ray's weight), then the nearest hit
                  (Nearest), or the sky (Sky) when there is none
     shade        local illumination at the hit (Hit): the layer's normal, pigment and k_r, and
                  each light sample through its shadow feeler (Layer, Lighting, Light, Shadow)
     transmitted  the transmitted ray, weighted by k_t; [refract]: Snell's law, or total internal
                  reflection
     reflected    the reflected ray R = −E + 2(N·E)N, weighted by k_r (Optics)

   The lecture adds k_r·RayTrace(R) before k_t·RayTrace(T); POV-Ray traces the transmitted ray
   first, and so does this tracer, because the order shows in the shadow cache. Secondary rays
   leave the hit through Hit.spawn; what a ray meets on its way to a hit is Segment's. A texture
   other than one plain layer is walked down to its layers by Textured, and [lighted] shades
   them (POV-Ray's ComputeLightedTexture, docs/textures.md). *)

open Compiled
open Context

let f32 = Precision.f32

type result = Traced.t = { r : float; g : float; b : float; tr : float }
type nonrec ctx = Context.t

let make_ctx = Context.make
let renew_ctx = Context.renew

let black = Traced.black

(* ComputeReflection: the film's interference tints the reflected colour too *)
let irid_reflected ctx (s : surface) rd d n p (c : result) : result =
  let k = Lighting.iridescence ctx.scene s rd d n p (Rgb.make c.r c.g c.b) in
  { r = k.r; g = k.g; b = k.b; tr = 0. }

(* What the transmitted ray [ct] adds to the colour [local] (§6.3): times the legacy refraction
   and what met the ray on its way to the hit (its interior's fade, when it travelled inside the
   object), filtered by [filter] unless it was totally reflected ([tir]); the colour, the
   transmittance the antialiasing compares, and [tir]. *)
let add_transmitted (h : Hit.t) (local : Rgb.t) (ct : result) tir (filter : Rgb.t) trans =
  let obj = h.obj in
  let att = Segment.through h.ray.kind obj h.ray.interiors h.depth (Rgb.grey obj.old_refract) in
  if tir then (Rgb.make (f32 (local.r +. f32 (att.r *. ct.r))) (f32 (local.g +. f32 (att.g *. ct.g))) (f32 (local.b +. f32 (att.b *. ct.b))), 0., true)
  else
    ( Rgb.make
        (f32 (local.r +. f32 (f32 (att.r *. ct.r) *. filter.r)))
        (f32 (local.g +. f32 (f32 (att.g *. ct.g) *. filter.g)))
        (f32 (local.b +. f32 (f32 (att.b *. ct.b) *. filter.b))),
      f32 (Rgb.intensity att *. ct.tr *. trans),
      false )

(* a reflected colour [c] added to [acc], weighed by [refl] and through the reflection exponent [e] *)
let add_reflection e (refl : Rgb.t) (c : result) (acc : result) =
  if e <> 1. then
    let ie = 1. /. e in
    let ie = f32 ie in
    { r = f32 (acc.r +. (refl.r *. Float.pow c.r ie)); g = f32 (acc.g +. (refl.g *. Float.pow c.g ie)); b = f32 (acc.b +. (refl.b *. Float.pow c.b ie)); tr = acc.tr }
  else { r = f32 (acc.r +. f32 (refl.r *. c.r)); g = f32 (acc.g +. f32 (refl.g *. c.g)); b = f32 (acc.b +. f32 (refl.b *. c.b)); tr = acc.tr }

(* The mirror direction R = −E + 2(N·E)N of the ray [d] (E = −d, the way to the eye) off the layer
   normal [n], made unit; off a normal bent by a pattern, kept above the shape's own normal [raw]
   (§5.3). *)
let mirror (d : Vec.t) (n : Vec.t) ~raw (bump : bump) =
  match bump with Smooth -> Vec.normalize (Vec.madd d (-2. *. Vec.dot d n) n) | Bumpy _ -> Optics.bent_reflection d n raw

(* whether two layer normals differ by more than EPSILON in some coordinate *)
let differs (a : Vec.t) (b : Vec.t) =
  Float.abs (a.x -. b.x) > Precision.epsilon || Float.abs (a.y -. b.y) > Precision.epsilon || Float.abs (a.z -. b.z) > Precision.epsilon

(* Trace a ray: the colour seen along it. *)
let rec trace_ray ctx (ray : Ray.t) : result =
  let sc = ctx.scene in
  (* termination: the trace level reached max_trace_level, or the ray's weight fell below
     adc_bailout (§7) *)
  if ray.level >= sc.max_trace_level || ray.weight < sc.adc_bailout then black
  else
    (* the nearest hit among the objects this kind of ray can meet (§16.6); a ray that meets
       nothing sees the sky *)
    let f = Nearest.search ctx ray.kind (if ray.mirrored then sc.mirrored else sc.seen) ray.origin ray.dir ctx.min_depth infinity in
    if not (Nearest.hit f) then Sky.colour sc ray.dir
    else
      (* a continued ray (through an interface of equal indices) does not use up a level *)
      let level = match ray.kind with Continued -> ray.level | Camera | Reflected | Transmitted | Shadow -> ray.level + 1 in
      if level > ctx.stats.max_level then ctx.stats.max_level <- level;
      (* §3.2: the layer loop runs while the remaining translucency (1 at the start) exceeds
         adc_bailout *)
      if not (1. > sc.adc_bailout) then black else shade ctx (Hit.make ctx ray f ~level)

(* The colour of the surface at a hit (§6.5): local illumination, plus what the transmitted and
   reflected rays bring back. *)
and shade ctx (h : Hit.t) : result =
  match h.texture with
  | Plain s when not h.obj.uv_mapped ->
      (* a plain texture, one layer (the common case): the layer loop of ComputeLightedTexture run
         once, the layer seen through nothing *)
      let l = Layer.shade ctx h ~warps:[] ~trans:1. h.point s in
      let s = l.surface in
      let local, tr, tir =
        if not s.transparent then (l.local, 0., false)
        else
          let filter = Optics.conserved s l.reflectivity in
          transmitted ctx h l l.local filter (Floats.min 1. (Float.abs (Rgb.intensity filter)))
      in
      reflected ctx h ~tir ~top:l.normal l { r = local.r; g = local.g; b = local.b; tr }
  | Plain _ | Layered _ | Blended _ | Uv_mapped _ | Chosen _ | Cutaway -> Textured.colour ~lighted ctx h

(* ComputeLightedTexture: the layers [ls] (the top first) at the point [q], each lit and seen
   through the filter and transmit of the layers above it; then the transmitted ray, filtered by
   every layer, and each layer's reflected ray. *)
and lighted ctx (h : Hit.t) (ls : surface array) q warps : result =
  let sc = ctx.scene in
  let count = Array.length ls in
  (* the layer loop: [res] the colour so far, [filter] the filter colour of the layers shaded,
     [trans] the translucency left; the layers shaded, the last first *)
  let rec layers i (res : Rgb.t) (filter : Rgb.t) trans shaded =
    if not (i < count && trans > sc.adc_bailout) then (res, filter, trans, shaded)
    else
      let l = Layer.shade ctx h ~warps ~trans q ls.(i) in
      let local = l.local and s = l.surface and refl = l.reflectivity in
      let res = Rgb.make (f32 (res.r +. f32 (local.r *. filter.r))) (f32 (res.g +. f32 (local.g *. filter.g))) (f32 (res.b +. f32 (local.b *. filter.b))) in
      (* the filter colour left for the layers below and what lies behind *)
      let t = s.filcol in
      let fc = Rgb.make (f32 (filter.r *. t.r)) (f32 (filter.g *. t.g)) (f32 (filter.b *. t.b)) in
      let k x = f32 (Floats.min 1. (1. -. x)) in
      let filter = if s.conserve then Rgb.make (f32 (fc.r *. k refl.r)) (f32 (fc.g *. k refl.g)) (f32 (fc.b *. k refl.b)) else fc in
      let trans = Floats.min 1. (Float.abs (f32 (Rgb.intensity filter))) in
      layers (i + 1) res filter trans (l :: shaded)
  in
  let local, filter, trans, shaded = layers 0 Rgb.black Rgb.white 1. [] in
  match List.rev shaded with
  | [] -> black (* never: [trace_ray] shades a hit only when 1 > adc_bailout, so the top layer is shaded *)
  | top :: _ as shaded ->
      (* the transmitted ray, filtered by every layer; then each layer's reflected ray *)
      let local, tr, tir = transmitted ctx h top local filter trans in
      List.fold_left (fun acc l -> reflected ctx h ~tir ~top:top.normal l acc) { r = local.r; g = local.g; b = local.b; tr } shaded

(* The transmitted ray, weighted by k_t, the filter colour [filter] (§6.1), traced when the
   translucency [trans] left exceeds adc_bailout, through the [top] layer's normal; the colour
   [local] with what it brings back added, its transmittance, and whether it was totally
   reflected. POV-Ray traces it before the reflected rays, and the order shows: their shadow
   feelers share the shadow cache. *)
and transmitted ctx (h : Hit.t) (top : Layer.t) (local : Rgb.t) (filter : Rgb.t) trans =
  if not (trans > ctx.scene.adc_bailout) then (local, 0., false)
  else
    let weight = f32 (h.ray.weight *. Floats.max (Float.abs filter.r) (Floats.max (Float.abs filter.g) (Float.abs filter.b))) in
    let ct, tir = refract ctx h ~weight top in
    add_transmitted h local ct tir filter trans

(* §6.2: the transmitted ray by Snell's law, n₁ sin θ₁ = n₂ sin θ₂, with the ratio of the indices
   of the interiors the ray leaves and enters; its colour, and whether total internal reflection
   happened (no real θ₂: the ray is reflected instead). *)
and refract ctx (h : Hit.t) ~weight (top : Layer.t) : result * bool =
  let sc = ctx.scene and obj = h.obj and d = h.ray.dir and interiors = h.ray.interiors in
  let ior, inner =
    match interiors with
    | [] -> (1. /. obj.interior.ior, [ obj.iid ])
    | last :: rest when last = obj.iid -> (obj.interior.ior /. (match rest with [] -> 1. | l :: _ -> sc.objects.(l).interior.ior), rest)
    | _ when List.mem obj.iid interiors -> (1., Optics.remove obj.iid interiors)
    | last :: _ -> (sc.objects.(last).interior.ior /. obj.interior.ior, obj.iid :: interiors)
  in
  ctx.stats.refracted_rays <- ctx.stats.refracted_rays + 1;
  if Float.abs (ior -. 1.) < Precision.epsilon then
    (* a continued ray: same direction, no new trace level *)
    (trace_ray ctx (Hit.spawn ctx h Continued ~weight ~interiors:inner d), false)
  else
    let n = top.normal in
    let dn = Vec.dot d n in
    let nn, nl = if dn <= 0. then (-.dn, n) else (dn, Vec.neg n) in
    (* cos² θ₂ = 1 − (n₁/n₂)²(1 − cos² θ₁) *)
    let t = 1. +. (ior *. ior *. ((nn *. nn) -. 1.)) in
    if t < 0. then
      (* total internal reflection: a reflected ray (§16.6) *)
      (trace_ray ctx (Hit.spawn ctx h Reflected ~weight ~interiors (mirror d n ~raw:h.normal top.surface.bump)), true)
    else
      let dir = Vec.add (Vec.scale ior d) (Vec.scale ((ior *. nn) -. sqrt t) nl) in
      (trace_ray ctx (Hit.spawn ctx h Transmitted ~weight ~interiors:inner dir), false)

(* The layer [l]'s reflected ray R, weighted by k_r (§5.3), added to [acc]; none after total
   internal reflection ([tir], which was the reflected ray already) unless the layer's normal is
   not the [top] layer's. *)
and reflected ctx (h : Hit.t) ~tir ~(top : Vec.t) (l : Layer.t) (acc : result) : result =
  let n = l.normal in
  if ((not tir) || differs top n) && not (Rgb.is_zero l.reflectivity) then begin
    let s = l.surface and d = h.ray.dir in
    let rd = mirror d n ~raw:h.normal s.bump in
    ctx.stats.reflected_rays <- ctx.stats.reflected_rays + 1;
    let c = trace_ray ctx (Hit.spawn ctx h Reflected ~weight:l.weight ~interiors:h.ray.interiors rd) in
    let c = if s.irid > 0. then irid_reflected ctx s rd d n h.point c else c in
    add_reflection s.refl.exponent l.reflectivity c acc
  end
  else acc

let trace ctx ~level ~weight ~interiors ~continued o d = trace_ray ctx (Ray.start ~level ~weight ~interiors ~continued o d)
