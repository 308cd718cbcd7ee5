(* The recursive Whitted tracer, with the steps of the lecture it follows: trace a ray (stopped by
   termination: the trace level or the ray's weight) → nearest hit → local illumination (ambient,
   diffuse, specular, each light through its shadow feeler) → transmitted ray → reflected ray. The
   lecture adds k_r·RayTrace(R) before k_t·RayTrace(T); POV-Ray traces the transmitted ray first,
   and so does this tracer, because the order shows in the shadow cache. POVRAY-3.7 §2–§7. The colour seen along a ray is
   a function of the compiled scene and the ray; what each step needs lives in a module of its own:
   Nearest (the nearest hit and POV-Ray's tie rules), Normals (a texture's normal bending the
   surface normal), Lighting and Shadow (local illumination and shadow feelers), Optics (Fresnel,
   interiors, fade), Sky, Robust (the robust mode's origins). *)

open Compiled
open Context

let f32 = Precision.f32

type result = Traced.t = { r : float; g : float; b : float; tr : float }
type nonrec ctx = Context.t

(* A context for one block. POV-Ray's facets cache belongs to a render thread, and a block is
   rendered as by a fresh thread: the scene's cache is emptied first. *)
let make_ctx ?robust (sc : Compiled.t) stats =
  Normals.reset_facets sc.facets;
  Context.make ?robust sc stats

let black = Traced.black

(* ComputeReflection's direction off a bent normal [n]: the mirror direction, unless it points
   below the surface by the raw normal [raw] (the "reflection bugfix" of trace.cpp): then the
   mirror direction off [raw] when it is below the bent normal's plane too, else the mirror
   direction reflected again in the raw normal's plane. Normalised last. *)
let bent_reflection (d : Vec.t) (n : Vec.t) (raw : Vec.t) =
  let r = Vec.madd d (-2. *. Vec.dot d n) n in
  let below = Vec.dot r raw in
  let r =
    if below < 0. then if Vec.dot r n < 0. then Vec.madd d (-2. *. Vec.dot d raw) raw else Vec.madd r (below *. -2.) raw
    else r
  in
  Vec.normalize r

(* Trace a ray. §16.6: a ray is a reflection ray ([reflected]) when it or an ancestor was
   reflected, else an image ray; each kind searches the objects it can meet. *)
let rec trace_ray ctx ~reflected ~level ~weight ~interiors ~continued (o : Vec.t) (d : Vec.t) : result =
  let sc = ctx.scene in
  (* termination: the trace level reached max_trace_level, or the ray's weight fell below
     adc_bailout (§7) *)
  if level >= sc.max_trace_level || weight < sc.adc_bailout then black
  else
    (* the nearest hit; a ray that meets nothing sees the sky *)
    let i = Nearest.search ctx (if reflected then sc.mirrored else sc.seen) o d ctx.min_depth infinity in
    if i < 0 then Sky.colour sc d
    else
      (* a continued ray (through an interface of equal indices) does not use up a level *)
      let level = if continued then level else level + 1 in
      if level > ctx.stats.max_level then ctx.stats.max_level <- level;
      shade ctx ~reflected sc.objects.(i) ctx.found.part ctx.reach.depth ~level ~weight ~interiors o d

(* The colour of the surface hit at [depth] along the ray (§6.5): local illumination, plus what the
   transmitted and reflected rays bring back. *)
and shade ctx ~reflected obj part depth ~level ~weight ~interiors (o : Vec.t) (d : Vec.t) : result =
  let sc = ctx.scene in
  (* §3.2: the layer loop runs while the remaining translucency (1 at the start) exceeds adc_bailout *)
  if not (1. > sc.adc_bailout) then black
  else
    (* the hit point P, its surface (a pattern is evaluated there, §17.1) and its normal N, turned
       toward the ray (§3.1) *)
    let p = Vec.madd o depth d in
    let p = if ctx.robust then Shape.refine obj p else p in
    let s = Surfaces.at obj part in
    let n = Shape.normal obj part p in
    let n = if Vec.dot n d > 0. then Vec.neg n else n in
    (* where secondary rays leave from in the robust mode *)
    let ng = if ctx.robust then Shape.geometric_normal obj part p else n in
    (* normal.cpp: a texture's normal bends N before the pigment is evaluated, whose slope and
       aoi patterns see the bent normal [pn]; [sn], the bent normal made unit, shades, reflects
       and refracts, and the raw N keeps the reflected ray on the surface's side (trace.cpp) *)
    let uv = if s.needs_uv then Shape.uv obj part p else Vec.zero in
    let pn = match s.bump with Smooth -> n | Bumpy nm -> Normals.perturb ~facets:sc.facets sc.noise_generator nm p { Patterns.normal = n; dir = d; uv } n in
    let s = match s.paint with Fixed -> s | Varying at -> at { Patterns.normal = pn; dir = d; uv } p in
    let sn = match s.bump with Smooth -> n | Bumpy nm -> Normals.layer_normal nm pn in
    let e = if ctx.robust then Robust.error_bound o p obj.mag else 0. in
    (* k_r, the reflection colour at the cosine of incidence N·E (E = −d, the way to the eye) *)
    let ci = -.Vec.dot d sn in
    let refl = if s.reflects then Optics.reflectivity sc s obj interiors ci else Rgb.black in
    (* §5.2: the reflected ray's weight, taken before the metallic tint *)
    let w_refl =
      f32 (if s.refl.fresnel then weight *. Rgb.max3 refl else weight *. Float.max (Rgb.max3 s.refl.rmax) (Rgb.max3 s.refl.rmin))
    in
    let refl = if s.reflects && s.refl.refl_metallic <> 0. then Lighting.metallic_factor s.refl.refl_metallic ci s.colour refl else refl in
    (* local illumination: ambient and emission, then each light through its shadow feeler *)
    let local = if s.lit then Lighting.add_lights ctx ~level ~di:obj.double_illuminate s p sn ng e d interiors s.emitted else s.emitted in
    (* the transmitted ray, weighted by k_t, the filter colour (§6). POV-Ray traces it before the
       reflected ray, and the order shows: both rays' shadow feelers share the shadow cache *)
    let local, tr, tir =
      if not s.transparent then (local, 0., false)
      else
        let filcol = Optics.conserved s refl in
        let trans = Float.min 1. (Float.abs (Rgb.intensity filcol)) in
        (* a ray too weak to matter (below adc_bailout) is not traced *)
        if not (trans > sc.adc_bailout) then (local, 0., false)
        else
          let w = f32 (weight *. Float.max (Float.abs filcol.r) (Float.max (Float.abs filcol.g) (Float.abs filcol.b))) in
          let ct, tir = refract ctx ~reflected obj ~level ~weight:w ~interiors p ng e d sn ~raw:n ~bump:s.bump in
          (* the interior's fade when the ray travelled inside [obj] *)
          let att = Rgb.grey obj.old_refract in
          let att = if Optics.fades obj && List.mem obj.iid interiors then Optics.fade obj depth att else att in
          if tir then (Rgb.make (f32 (local.r +. f32 (att.r *. ct.r))) (f32 (local.g +. f32 (att.g *. ct.g))) (f32 (local.b +. f32 (att.b *. ct.b))), 0., true)
          else
            ( Rgb.make
                (f32 (local.r +. f32 (f32 (att.r *. ct.r) *. filcol.r)))
                (f32 (local.g +. f32 (f32 (att.g *. ct.g) *. filcol.g)))
                (f32 (local.b +. f32 (f32 (att.b *. ct.b) *. filcol.b))),
              f32 (Rgb.intensity att *. ct.tr *. trans),
              false )
    in
    (* the reflected ray R = −E + 2(N·E)N, weighted by k_r (§5.3); none after total internal
       reflection, which was the reflected ray already *)
    if tir || Rgb.is_zero refl then { r = local.r; g = local.g; b = local.b; tr }
    else
      let rd = match s.bump with Smooth -> Vec.normalize (Vec.madd d (-2. *. Vec.dot d n) n) | Bumpy _ -> bent_reflection d sn n in
      ctx.stats.reflected_rays <- ctx.stats.reflected_rays + 1;
      let c = trace_ray ctx ~reflected:true ~level ~weight:w_refl ~interiors ~continued:false (Robust.origin ctx p ng e rd) rd in
      let e = s.refl.exponent in
      if e <> 1. then
        let ie = 1. /. e in
        let ie = f32 ie in
        { r = f32 (local.r +. (refl.r *. Float.pow c.r ie)); g = f32 (local.g +. (refl.g *. Float.pow c.g ie)); b = f32 (local.b +. (refl.b *. Float.pow c.b ie)); tr }
      else { r = f32 (local.r +. f32 (refl.r *. c.r)); g = f32 (local.g +. f32 (refl.g *. c.g)); b = f32 (local.b +. f32 (refl.b *. c.b)); tr }

(* §6.2: the transmitted ray by Snell's law, n₁ sin θ₁ = n₂ sin θ₂, with the ratio of the indices
   of the interiors the ray leaves and enters; its colour, and whether total internal reflection
   happened (no real θ₂: the ray is reflected instead). *)
and refract ctx ~reflected obj ~level ~weight ~interiors p ng e d n ~raw ~bump : result * bool =
  let sc = ctx.scene in
  let ior, inner =
    match interiors with
    | [] -> (1. /. obj.ior, [ obj.iid ])
    | last :: rest when last = obj.iid -> (obj.ior /. (match rest with [] -> 1. | l :: _ -> sc.objects.(l).ior), rest)
    | _ when List.mem obj.iid interiors -> (1., Optics.remove obj.iid interiors)
    | last :: _ -> (sc.objects.(last).ior /. obj.ior, obj.iid :: interiors)
  in
  ctx.stats.refracted_rays <- ctx.stats.refracted_rays + 1;
  if Float.abs (ior -. 1.) < Precision.epsilon then
    (* a continued ray: same direction, no new trace level *)
    (trace_ray ctx ~reflected ~level ~weight ~interiors:inner ~continued:true (Robust.origin ctx p ng e d) d, false)
  else
    let dn = Vec.dot d n in
    let nn, nl = if dn <= 0. then (-.dn, n) else (dn, Vec.neg n) in
    (* cos² θ₂ = 1 − (n₁/n₂)²(1 − cos² θ₁) *)
    let t = 1. +. (ior *. ior *. ((nn *. nn) -. 1.)) in
    if t < 0. then
      let rd = match bump with Smooth -> Vec.normalize (Vec.madd d (-2. *. dn) n) | Bumpy _ -> bent_reflection d n raw in
      (* total internal reflection: a reflected ray (§16.6) *)
      (trace_ray ctx ~reflected:true ~level ~weight ~interiors ~continued:false (Robust.origin ctx p ng e rd) rd, true)
    else
      let dir = Vec.add (Vec.scale ior d) (Vec.scale ((ior *. nn) -. sqrt t) nl) in
      (trace_ray ctx ~reflected ~level ~weight ~interiors:inner ~continued:false (Robust.origin ctx p ng e dir) dir, false)

let trace ctx ~level ~weight ~interiors ~continued o d = trace_ray ctx ~reflected:false ~level ~weight ~interiors ~continued o d
