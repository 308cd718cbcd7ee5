(* The recursive Whitted tracer, with the steps of the lecture it follows: trace a ray (stopped by
   termination: the trace level or the ray's weight) → nearest hit → local illumination (ambient,
   diffuse, specular, each light through its shadow feeler) → transmitted ray → reflected ray. The
   lecture adds k_r·RayTrace(R) before k_t·RayTrace(T); POV-Ray traces the transmitted ray first,
   and so does this tracer, because the order shows in the shadow cache. docs/povray-rules.md §2–§7. The colour seen along a ray is
   a function of the compiled scene and the ray; what each step needs lives in a module of its own:
   Nearest (the nearest hit and POV-Ray's tie rules), Normals (a texture's normal bending the
   surface normal), Lighting and Shadow (local illumination and shadow feelers), Optics (Fresnel,
   interiors, fade), Sky, Robust (the robust mode's origins). A plain texture (one layer) is shaded
   by [shade] itself; layered and patterned textures by [texture_colour] and [lighted], POV-Ray's
   ComputeOneTextureColour and ComputeLightedTexture (docs/textures.md). *)

open Compiled
open Context

let f32 = Precision.f32

type result = Traced.t = { r : float; g : float; b : float; tr : float }
type nonrec ctx = Context.t

let make_ctx = Context.make
let renew_ctx = Context.renew

let black = Traced.black

(* What every layer and entry of a texture shaded at one hit shares: the object, the hit point P
   (where lights and secondary rays are taken from), the shape's normal N turned toward the ray,
   the ray, and the perturbed normal the slope and aoi patterns see, which each normal pattern
   shaded replaces (POV-Ray's Intersection.PNormal). *)
type hit = {
  hobj : obj;
  hpart : int;  (** the part of it hit (a mesh face …) *)
  hp : Vec.t;
  hn : Vec.t;
  hng : Vec.t;  (** where secondary rays leave from in the robust mode *)
  he : float;
  hd : Vec.t;
  hdepth : float;
  hlevel : int;
  hweight : float;
  hinteriors : int list;
  hreflected : bool;
  memo : Lighting.memo;
  mutable pnormal : Vec.t;
}

(* A layer once shaded: what its reflected ray needs (POV-Ray's WNRX list) *)
type shaded = { lsurf : surface; lnormal : Vec.t; lrefl : Rgb.t; lweight : float }

(* ComputeReflection: the film's interference tints the reflected colour too *)
let irid_reflected ctx (s : surface) rd d n p (c : result) : result =
  let k = Lighting.iridescence ctx.scene s rd d n p (Rgb.make c.r c.g c.b) in
  { r = k.r; g = k.g; b = k.b; tr = 0. }

(* What the transmitted ray [ct] adds to the colour [local]: faded by the interior when the ray
   travelled inside [obj] ([depth] along it), filtered by [filcol] unless it was totally reflected
   ([tir]); the colour, the transmittance the antialiasing compares, and [tir]. *)
let add_transmitted (obj : obj) interiors depth (local : Rgb.t) (ct : result) tir (filcol : Rgb.t) trans =
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

(* a reflected colour [c] added to [acc], weighed by [refl] and through the reflection exponent [e] *)
let add_reflection e (refl : Rgb.t) (c : result) (acc : result) =
  if e <> 1. then
    let ie = 1. /. e in
    let ie = f32 ie in
    { r = f32 (acc.r +. (refl.r *. Float.pow c.r ie)); g = f32 (acc.g +. (refl.g *. Float.pow c.g ie)); b = f32 (acc.b +. (refl.b *. Float.pow c.b ie)); tr = acc.tr }
  else { r = f32 (acc.r +. f32 (refl.r *. c.r)); g = f32 (acc.g +. f32 (refl.g *. c.g)); b = f32 (acc.b +. f32 (refl.b *. c.b)); tr = acc.tr }

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
    (* the hit point P and its normal N, turned toward the ray (§3.1) *)
    let p = if ctx.robust then Shape.refine obj (Vec.madd o depth d) else Shape.hit_point ctx.shapes obj o depth d in
    let n = Shape.hit_normal ctx.shapes obj part p in
    let dn = Vec.dot n d in
    let tex = if obj.inner_tex = None then Surfaces.at obj part else Surfaces.seen obj part ~inside:(if obj.inverted then dn < 0. else dn > 0.) in
    let n = if dn > 0. then Vec.neg n else n in
    (* where secondary rays leave from in the robust mode *)
    let ng = if ctx.robust then Shape.geometric_normal ctx.shapes obj part p else n in
    let e = if ctx.robust then Robust.error_bound ~shift:ctx.scene.shift o p obj.mag else 0. in
    match tex with
    | Plain s when not obj.uv_mapped ->
        (* a plain texture, one layer (the common case): the layer loop of ComputeLightedTexture
           run once *)
        (* normal.cpp: a texture's normal bends N before the pigment is evaluated, whose slope and aoi
           patterns see the bent normal [pn]; [sn], the bent normal made unit, shades, reflects and
           refracts, and the raw N keeps the reflected ray on the surface's side (trace.cpp) *)
        let uv = if s.needs_uv then Shape.uv ctx.shapes obj part p else Vec.zero in
        let pn = match s.bump with Smooth -> n | Bumpy nm -> Normals.perturb ~facets:ctx.facets sc.noise_generator nm p { Patterns.normal = n; dir = d; uv } n in
        let s = match s.paint with Fixed -> s | Varying at -> at { Patterns.normal = pn; dir = d; uv } p in
        let sn = match s.bump with Smooth -> n | Bumpy nm -> Normals.layer_normal nm pn in
        (* k_r, the reflection colour at the cosine of incidence N·E (E = −d, the way to the eye) *)
        let ci = -.Vec.dot d sn in
        let refl = if s.reflects then Optics.reflectivity sc s obj interiors ci else Rgb.black in
        (* §5.2: the reflected ray's weight, taken before the metallic tint *)
        let w_refl =
          f32 (if s.refl.fresnel then weight *. Rgb.max3 refl else weight *. Float.max (Rgb.max3 s.refl.rmax) (Rgb.max3 s.refl.rmin))
        in
        let refl = if s.reflects && s.refl.refl_metallic <> 0. then Lighting.metallic_factor s.refl.refl_metallic ci s.colour refl else refl in
        (* local illumination: ambient and emission, then each light through its shadow feeler *)
        let local = if s.lit then Lighting.add_lights ctx ~memo:Lighting.no_memo ~level ~di:obj.double_illuminate s p sn ng e d interiors s.emitted else s.emitted in
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
              add_transmitted obj interiors depth local ct tir filcol trans
        in
        (* the reflected ray R = −E + 2(N·E)N, weighted by k_r (§5.3); none after total internal
           reflection, which was the reflected ray already *)
        if tir || Rgb.is_zero refl then { r = local.r; g = local.g; b = local.b; tr }
        else
          let rd = match s.bump with Smooth -> Vec.normalize (Vec.madd d (-2. *. Vec.dot d n) n) | Bumpy _ -> bent_reflection d sn n in
          ctx.stats.reflected_rays <- ctx.stats.reflected_rays + 1;
          let c = trace_ray ctx ~reflected:true ~level ~weight:w_refl ~interiors ~continued:false (Robust.origin ctx p ng e rd) rd in
          let c = if s.irid > 0. then irid_reflected ctx s rd d sn p c else c in
          add_reflection s.refl.exponent refl c { r = local.r; g = local.g; b = local.b; tr }
    | Plain _ | Layered _ | Blended _ | Uv_mapped _ | Chosen _ | Cutaway -> shade_textured ctx ~reflected obj part tex p n ng e depth ~level ~weight ~interiors d

(* Any other texture (ComputeTextureColour): layers, patterned textures, uv_mapping, cutaways. *)
and shade_textured ctx ~reflected obj part tex p n ng e depth ~level ~weight ~interiors d =
  let sc = ctx.scene in
  let at = { hobj = obj; hpart = part; hp = p; hn = n; hng = ng; he = e; hd = d; hdepth = depth; hlevel = level; hweight = weight; hinteriors = interiors; hreflected = reflected; memo = Lighting.memo sc; pnormal = n } in
  (* an object's uv_mapping: every texture is evaluated at the hit's (u, v, 0) *)
  let q = if obj.uv_mapped then Shape.uv ctx.shapes obj part p else p in
  match tex with
  | Cutaway ->
      (* the textures of the members around the point, weighed *)
      List.fold_left
        (fun (acc : result) (w, t) ->
          if w < sc.adc_bailout then acc
          else
            let c = texture_colour ctx at t q [] in
            { r = f32 (acc.r +. f32 (w *. c.r)); g = f32 (acc.g +. f32 (w *. c.g)); b = f32 (acc.b +. f32 (w *. c.b)); tr = f32 (acc.tr +. f32 (w *. c.tr)) })
        black (Surfaces.cutaway ctx.stack sc obj p)
  | Plain _ | Layered _ | Blended _ | Uv_mapped _ | Chosen _ -> texture_colour ctx at tex q []

(* The reflected ray off the normal [n] ([raw], the shape's own, keeps it on the surface's side
   when [n] is bent) and what it brings back. *)
and reflect ctx ~level ~weight ~interiors (s : surface) p ng e d n ~raw =
  let rd = match s.bump with Smooth -> Vec.normalize (Vec.madd d (-2. *. Vec.dot d n) n) | Bumpy _ -> bent_reflection d n raw in
  ctx.stats.reflected_rays <- ctx.stats.reflected_rays + 1;
  let c = trace_ray ctx ~reflected:true ~level ~weight ~interiors ~continued:false (Robust.origin ctx p ng e rd) rd in
  if s.irid > 0. then irid_reflected ctx s rd d n p c else c

(* ComputeOneTextureColour: a texture's colour at the point [q] where its pigments and normals are
   evaluated ([warps]: the patterned textures it lies in, the outermost first). *)
and texture_colour ctx at tex q warps : result =
  match tex with
  | Plain s -> lighted ctx at [| s |] q warps
  | Layered ls -> lighted ctx at ls q warps
  | Cutaway -> black (* never inside another texture *)
  | Chosen { cwarp; choose; textures; cwarps } ->
      let tq = cwarp q in
      texture_colour ctx at textures.(choose tq) tq (warps @ [ cwarps ])
  | Uv_mapped { uinner; uwarps } -> texture_colour ctx at uinner (Shape.uv ctx.shapes at.hobj at.hpart at.hp) (warps @ [ uwarps ])
  | Blended b ->
      let warps = warps @ [ b.nwarps ] in
      let tq = b.warp q in
      if b.average then
        (* ComputeAverageTextureColours: the entries weighed by their values, summed in single
           precision, over the sum of the weights *)
        let acc = ref black and total = ref 0. in
        Array.iteri
          (fun i t ->
            let c = texture_colour ctx at t tq warps in
            let v = b.values.(i) in
            let a = !acc in
            acc := { r = f32 (a.r +. f32 (c.r *. v)); g = f32 (a.g +. f32 (c.g *. v)); b = f32 (a.b +. f32 (c.b *. v)); tr = f32 (a.tr +. f32 (c.tr *. v)) };
            total := f32 (!total +. v))
          b.entries;
        let a = !acc and t = !total in
        { r = f32 (a.r /. t); g = f32 (a.g /. t); b = f32 (a.b /. t); tr = f32 (a.tr /. t) }
      else
        let v = b.value { Patterns.normal = at.pnormal; dir = at.hd; uv = Vec.zero } tq in
        let prev, cur = Surfaces.around b.values v in
        let c1 = texture_colour ctx at b.entries.(cur) tq warps in
        if prev = cur then c1
        else
          let c2 = texture_colour ctx at b.entries.(prev) tq warps in
          (* the map's values are single precision, and so is their difference (the value's own
             distance from the lower one is taken in double) *)
          let v1 = (v -. b.values.(prev)) /. f32 (b.values.(cur) -. b.values.(prev)) in
          let v2 = 1. -. v1 in
          let mix x y = f32 (f32 (v1 *. x) +. f32 (v2 *. y)) in
          { r = mix c1.r c2.r; g = mix c1.g c2.g; b = mix c1.b c2.b; tr = mix c1.tr c2.tr }

(* ComputeLightedTexture: the layers [ls] (the top first) at the point [q], each lit and seen
   through the filter and transmit of the layers above it; then the transmitted ray, filtered by
   every layer, and each layer's reflected ray. *)
and lighted ctx at (ls : surface array) q warps : result =
  let sc = ctx.scene in
  let obj = at.hobj and d = at.hd and n = at.hn in
  let count = Array.length ls in
  (* the layer loop: [res] the colour so far, [filcol] the filter colour of the layers shaded, [trans]
     the translucency left; each layer shaded leaves what its reflected ray needs in [shaded] (the
     last shaded first) *)
  let rec layers i (res : Rgb.t) (filcol : Rgb.t) trans shaded =
    if not (i < count && trans > sc.adc_bailout) then (res, filcol, trans, shaded)
    else
      let s = ls.(i) in
      let uv = if s.needs_uv then Shape.uv ctx.shapes obj at.hpart at.hp else Vec.zero in
      (* the layer's normal: bent by its normal pattern, in the space of the patterned textures
         around it *)
      let ln =
        match s.bump with
        | Smooth -> n
        | Bumpy nm ->
            let wn = List.fold_left (fun v ws -> Normals.warp_normal ws ~keep_scale:false v) n warps in
            let pn = Normals.perturb ~facets:ctx.facets sc.noise_generator nm q { Patterns.normal = at.pnormal; dir = d; uv } wn in
            at.pnormal <- pn;
            List.fold_right (fun ws v -> Normals.unwarp_normal ws ~keep_scale:false v) warps (Normals.layer_normal nm pn)
      in
      let s = match s.paint with Fixed -> s | Varying f -> f { Patterns.normal = at.pnormal; dir = d; uv } q in
      let new_weight = at.hweight *. trans in
      let ci = -.Vec.dot d ln in
      let refl = if s.reflects then Optics.reflectivity sc s obj at.hinteriors ci else Rgb.black in
      let weight = f32 (if s.refl.fresnel then new_weight *. Rgb.max3 refl else new_weight *. Float.max (Rgb.max3 s.refl.rmax) (Rgb.max3 s.refl.rmin)) in
      let refl = if s.reflects && s.refl.refl_metallic <> 0. then Lighting.metallic_factor s.refl.refl_metallic ci s.colour refl else refl in
      let local =
        if s.lit then Lighting.add_lights ctx ~memo:at.memo ~level:at.hlevel ~di:obj.double_illuminate s at.hp ln at.hng at.he d at.hinteriors s.emitted
        else s.emitted
      in
      let res = Rgb.make (f32 (res.r +. f32 (local.r *. filcol.r))) (f32 (res.g +. f32 (local.g *. filcol.g))) (f32 (res.b +. f32 (local.b *. filcol.b))) in
      (* the filter colour left for the layers below and what lies behind *)
      let t = s.filcol in
      let fc = Rgb.make (f32 (filcol.r *. t.r)) (f32 (filcol.g *. t.g)) (f32 (filcol.b *. t.b)) in
      let k x = f32 (Float.min 1. (1. -. x)) in
      let filcol = if s.conserve then Rgb.make (f32 (fc.r *. k refl.r)) (f32 (fc.g *. k refl.g)) (f32 (fc.b *. k refl.b)) else fc in
      let trans = Float.min 1. (Float.abs (f32 (Rgb.intensity filcol))) in
      layers (i + 1) res filcol trans ({ lsurf = s; lnormal = ln; lrefl = refl; lweight = weight } :: shaded)
  in
  let local, f, trans, shaded = layers 0 Rgb.black Rgb.white 1. [] in
  let shaded = List.rev shaded in
  let top_normal = match shaded with l :: _ -> l.lnormal | [] -> n in
  let top = ls.(0) in
  (* the transmitted ray, filtered by every layer *)
  let local, tr, tir =
    if not (trans > sc.adc_bailout) then (local, 0., false)
    else
      let w = f32 (at.hweight *. Float.max (Float.abs f.r) (Float.max (Float.abs f.g) (Float.abs f.b))) in
      let ct, tir = refract ctx ~reflected:at.hreflected obj ~level:at.hlevel ~weight:w ~interiors:at.hinteriors at.hp at.hng at.he d top_normal ~raw:n ~bump:top.bump in
      add_transmitted obj at.hinteriors at.hdepth local ct tir f trans
  in
  (* each layer's reflected ray; after total internal reflection, only those whose normal is not
     the top layer's *)
  List.fold_left
    (fun acc l ->
      let ni = l.lnormal in
      let differs = Float.abs (top_normal.x -. ni.x) > Precision.epsilon || Float.abs (top_normal.y -. ni.y) > Precision.epsilon || Float.abs (top_normal.z -. ni.z) > Precision.epsilon in
      if ((not tir) || differs) && not (Rgb.is_zero l.lrefl) then
        let c = reflect ctx ~level:at.hlevel ~weight:l.lweight ~interiors:at.hinteriors l.lsurf at.hp at.hng at.he d ni ~raw:n in
        add_reflection l.lsurf.refl.exponent l.lrefl c acc
      else acc)
    { r = local.r; g = local.g; b = local.b; tr } shaded

(* §6.2: the transmitted ray by Snell's law, n₁ sin θ₁ = n₂ sin θ₂, with the ratio of the indices
   of the interiors the ray leaves and enters; its colour, and whether total internal reflection
   happened (no real θ₂: the ray is reflected instead). *)
and refract ctx ~reflected obj ~level ~weight ~interiors p ng e d n ~raw ~bump : result * bool =
  let sc = ctx.scene in
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
