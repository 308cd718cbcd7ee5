(* One layer of a texture shaded at a hit. *)

open Compiled
open Context

let f32 = Precision.f32

type t = { surface : surface; normal : Vec.t; reflectivity : Rgb.t; weight : float; local : Rgb.t }

(* a normal taken into the space of the patterned textures [warps] around a layer (the outermost
   first), and back *)
let warped warps n = List.fold_left (fun v ws -> Normals.warp_normal ws ~keep_scale:false v) n warps
let unwarped warps n = List.fold_right (fun ws v -> Normals.unwarp_normal ws ~keep_scale:false v) warps n

let[@inline] shade ctx (h : Hit.t) ~warps ~trans q (s : surface) =
  let sc = ctx.scene in
  let d = h.ray.dir and n = h.normal in
  let uv = if s.needs_uv then Shape.uv h.obj h.part h.crossing h.point else Vec.zero in
  (* normal.cpp: the layer's normal pattern bends N (in the space of the patterned textures around
     it) before its pigment is evaluated, whose slope and aoi patterns see the bent normal; that
     normal made unit shades, reflects and refracts *)
  let normal =
    match s.bump with
    | Smooth -> n
    | Bumpy nm ->
        let pn = Normals.perturb ~facets:ctx.facets sc.noise_generator nm q { Patterns.normal = h.pnormal; dir = d; uv } (warped warps n) in
        h.pnormal <- pn;
        unwarped warps (Normals.layer_normal nm pn)
  in
  let s = match s.paint with Fixed -> s | Varying at -> at { Patterns.normal = h.pnormal; dir = d; uv } q in
  (* k_r, the reflection colour at the cosine of incidence N·E (E = −d, the way to the eye) *)
  let ci = -.Vec.dot d normal in
  let refl = if s.reflects then Optics.reflectivity sc s h.obj h.ray.interiors ci else Rgb.black in
  (* §5.2: the reflected ray's weight, taken before the metallic tint *)
  let w = h.ray.weight *. trans in
  let weight = f32 (if s.refl.fresnel then w *. Floats.max3 refl else w *. Floats.max (Floats.max3 s.refl.rmax) (Floats.max3 s.refl.rmin)) in
  let refl = if s.reflects && s.refl.refl_metallic <> 0. then Lighting.metallic_factor s.refl.refl_metallic ci s.colour refl else refl in
  { surface = s; normal; reflectivity = refl; weight; local = Lighting.local ctx h s normal }
