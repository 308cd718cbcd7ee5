open Compiled

let epsilon = 1e-10
let f32 x = Int32.float_of_bits (Int32.bits_of_float x)

let finite (t : Transform.t) =
  List.for_all Float.is_finite
    [ t.m00; t.m01; t.m02; t.m10; t.m11; t.m12; t.m20; t.m21; t.m22; t.m30; t.m31; t.m32;
      t.i00; t.i01; t.i02; t.i10; t.i11; t.i12; t.i20; t.i21; t.i22; t.i30; t.i31; t.i32 ]

(* A shape ready to trace; None for a triangle that POV-Ray never hits (no area, or a standalone
   smooth triangle whose vertex normals straddle its face). *)
let prim_of (s : Scene.shape) =
  let sphere (c : Vec.t) r = { cx = c.x; cy = c.y; cz = c.z; radius = r; r2 = r *. r } in
  let plane (n : Vec.t) offset = { nx = n.x; ny = n.y; nz = n.z; dist = -.offset } in
  match s with
  | Sphere { centre; radius; trans = None } -> Some (Sphere (sphere centre radius))
  | Sphere { centre; radius; trans = Some etr } -> Some (Ellipsoid { sp = sphere centre radius; etr })
  | Plane { normal; offset; trans = None } -> Some (Plane (plane normal offset))
  | Plane { normal; offset; trans = Some ptr } ->
      (* the normal by the inverse transpose, normalised (§14.6): a constant of the object *)
      let pnormal = Transform.normalize (Transform.normal ptr normal) in
      Some (Plane_trans { pl = plane normal offset; ptr; pnormal })
  | Triangle { p1; p2; p3 } -> Option.map (fun t -> Triangle t) (Triangle.flat p1 p2 p3)
  | Smooth_triangle { p1; n1; p2; n2; p3; n3 } -> (
      match Triangle.smooth p1 n1 p2 n2 p3 n3 with Some (Ok t) -> Some (Smooth_triangle t) | None | Some (Error ()) -> None)
  | Mesh { mesh; trans = None; _ } -> Some (Mesh { mesh; tr = Transform.identity; moved = false })
  | Mesh { mesh; trans = Some tr; _ } -> Some (Mesh { mesh; tr; moved = true })
  | Box { lo; hi; trans } -> (
      let bx = { x0 = lo.x; y0 = lo.y; z0 = lo.z; x1 = hi.x; y1 = hi.y; z1 = hi.z } in
      match trans with None -> Some (Box bx) | Some btr -> Some (Box_trans { bx; btr }))
  | Cone { cylinder; dist; closed; trans; _ } ->
      (* a cylinder of radius 0 has no inverse transform: POV-Ray never hits it *)
      if finite trans then Some (Cone { ctr = trans; dist; cyl = cylinder; closed }) else None
  | Disc { normal; radius; hole; trans; _ } ->
      if finite trans then
        Some (Disc { dtr = trans; dnx = normal.x; dny = normal.y; dnz = normal.z; or2 = radius *. radius; ir2 = hole *. hole })
      else None
  | Torus { major; minor; sturm; trans } -> Some (Torus { Torus.major; minor; sturm; tr = trans })
  | Glyph { outline; depth; trans } -> if finite trans then Some (Glyph { Glyph.outline; depth; tr = trans }) else None
  | Csg _ -> None (* built by [scene], which numbers the members *)

(* Box::Inside: a closed box, its surface included *)
let in_box b (p : Vec.t) = not (p.x < b.x0 || p.x > b.x1 || p.y < b.y0 || p.y > b.y1 || p.z < b.z0 || p.z > b.z1)

(* Cone::Inside (§15.2, §15.3): closed shapes shrunk by EPSILON, open ones grown by it (an open
   cylinder still has a solid inside). *)
let in_cone c (p : Vec.t) =
  let q = Transform.inv_point c.ctr p in
  let offset = if c.closed then -.epsilon else epsilon in
  let w2 = (q.x *. q.x) +. (q.y *. q.y) in
  let out =
    if c.cyl then w2 > 1.0 +. offset || q.z < 0.0 -. offset || q.z > 1.0 +. offset
    else w2 > (q.z *. q.z) +. offset || q.z < c.dist -. offset || q.z > 1.0 +. offset
  in
  not out

(* Disc::Inside (§15.4): the open half-space behind the disc's plane, z < 0 in canonical space *)
let in_disc d (p : Vec.t) =
  let q = Transform.inv_point d.dtr p in
  q.z < 0.0

let rec inside stack shape (p : Vec.t) =
  match shape with
  | Csg { kind = Union | Merge; members } ->
      (* §16.3: inside any member, or inside every member *)
      Array.exists (fun m -> inside_member stack m p) members
  | Csg { kind = Intersection | Clipped; members } ->
      (* a clipped object's Inside asks its clip objects too (Inside_Object) *)
      Array.for_all (fun m -> inside_member stack m p) members
  | Cone c -> in_cone c p
  | Disc d -> in_disc d p
  | Box b -> in_box b p
  | Box_trans { bx; btr } -> in_box bx (Transform.inv_point btr p)
  | Torus t -> Torus.inside t p
  | Glyph g -> Glyph.inside g p
  | Sphere s ->
      let dx = p.x -. s.cx and dy = p.y -. s.cy and dz = p.z -. s.cz in
      (dx *. dx) +. (dy *. dy) +. (dz *. dz) < s.r2
  | Ellipsoid { sp = s; etr } ->
      (* Sphere::Inside in object space: (C − P')² < r² *)
      let q = Transform.inv_point etr p in
      let dx = s.cx -. q.x and dy = s.cy -. q.y and dz = s.cz -. q.z in
      (dx *. dx) +. (dy *. dy) +. (dz *. dz) < s.r2
  | Plane pl -> (p.x *. pl.nx) +. (p.y *. pl.ny) +. (p.z *. pl.nz) +. pl.dist < epsilon
  | Plane_trans { pl; ptr } ->
      let q = Transform.inv_point ptr p in
      (q.x *. pl.nx) +. (q.y *. pl.ny) +. (q.z *. pl.nz) +. pl.dist < epsilon
  | Triangle _ | Smooth_triangle _ -> false
  | Mesh m ->
      (* Mesh::Inside: the ray from P along the inside vector, both brought into mesh space and
         the direction renormalised *)
      if not m.moved then Mesh.inside m.mesh stack p
      else (
        match m.mesh.inside_vector with
        | None -> false
        | Some d -> Mesh.inside_along m.mesh stack (Transform.inv_point m.tr p) (Transform.normalize (Transform.inv_direction m.tr d)))

(* A CSG member's Inside: a primitive's negated when it is inverted; an inverted CSG was morphed
   and its own Inside already holds the inversion (§16.3). *)
and inside_member stack (m : obj) p =
  match m.shape with
  | Csg _ -> inside stack m.shape p
  | Sphere _ | Ellipsoid _ | Plane _ | Plane_trans _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Box_trans _ | Cone _
  | Disc _ | Torus _ | Glyph _ ->
      inside stack m.shape p <> m.inverted

(* The box of a bounded shape; None for an unbounded one. A transformed shape's box is its
   object-space box with the corners mapped (Recompute_BBox, §15.8). *)
(* SMALL_TOLERANCE: a disc's box is this thick on each side of its plane (§15.4) *)
let small_tolerance = 1e-3

let rec bounds = function
  | Csg { kind = Union | Merge; members } ->
      (* CSG::Compute_BBox: a union's or merge's box holds its members' boxes; an intersection's is
         the overlap of its members' that are not inverted (an inverted CSG, morphed, counts as
         inverted: its surfaces are bounded, its inside is not). A plane is unbounded here (POV-Ray
         bounds an axis-aligned one on one side: that changes only equal-depth ties). *)
      Array.fold_left
        (fun acc m ->
          match (acc, bounds m.shape) with
          | Some a, Some b -> Some (Array.init 6 (fun i -> if i < 3 then Float.min a.(i) b.(i) else Float.max a.(i) b.(i)))
          | None, _ | _, None -> None)
        (Some [| infinity; infinity; infinity; neg_infinity; neg_infinity; neg_infinity |])
        members
      |> Option.map (fun b -> if b.(0) > b.(3) then [| 0.; 0.; 0.; 0.; 0.; 0. |] else b)
  | Csg { kind = Intersection; members = [| ({ shape = Sphere _ | Ellipsoid _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Box_trans _ | Cone _ | Disc _ | Torus _ | Glyph _; _ } as m) |] }
    when m.inverted ->
      (* an inverted primitive written alone enters as an intersection of itself (Objects); POV-Ray
         keeps such a primitive's own box *)
      bounds m.shape
  | Csg { kind = Intersection | Clipped; members } ->
      let b =
        Array.fold_left
          (fun acc m ->
            match (m.inverted, acc, bounds m.shape) with
            | false, None, Some b -> Some b
            | false, Some a, Some b -> Some (Array.init 6 (fun i -> if i < 3 then Float.max a.(i) b.(i) else Float.min a.(i) b.(i)))
            | false, acc, None | true, acc, _ -> acc)
          None members
      in
      (* an empty overlap: nothing can be hit; POV-Ray then keeps its unbounded box *)
      Option.bind b (fun b -> if b.(0) > b.(3) || b.(1) > b.(4) || b.(2) > b.(5) then None else Some b)
  | Sphere s ->
      let r = Float.abs s.radius in
      Some [| s.cx -. r; s.cy -. r; s.cz -. r; s.cx +. r; s.cy +. r; s.cz +. r |]
  | Ellipsoid { sp = s; etr } ->
      let r = Float.abs s.radius in
      Some (Transform.bounds etr [| s.cx -. r; s.cy -. r; s.cz -. r; s.cx +. r; s.cy +. r; s.cz +. r |])
  | Plane _ | Plane_trans _ -> None
  | Triangle t | Smooth_triangle t -> Some (Triangle.bounds t)
  | Mesh m -> if m.moved then Some (Transform.bounds m.tr (Mesh.bounds m.mesh)) else Some (Mesh.bounds m.mesh)
  | Box b -> Some [| b.x0; b.y0; b.z0; b.x1; b.y1; b.z1 |]
  | Box_trans { bx = b; btr } -> Some (Transform.bounds btr [| b.x0; b.y0; b.z0; b.x1; b.y1; b.z1 |])
  | Cone c -> Some (Transform.bounds c.ctr [| -1.; -1.; c.dist; 1.; 1.; 1. |])
  | Disc d ->
      let r = sqrt d.or2 in
      Some (Transform.bounds d.dtr [| -.r; -.r; -.small_tolerance; r; r; small_tolerance |])
  | Torus t -> Some (Transform.bounds t.tr (Torus.box t))
  | Glyph g -> Some (Transform.bounds g.tr (Glyph.box g))

(* The largest coordinate magnitude of a shape: its box, or for a plane its point nearest the origin. *)
let magnitude shape =
  let max_abs a = Array.fold_left (fun m x -> Float.max m (Float.abs x)) 0. a in
  match (bounds shape, shape) with
  | Some b, _ -> max_abs b
  | None, Plane p -> Float.abs p.dist
  | None, Plane_trans { pl; ptr; _ } ->
      let q = Transform.point ptr (Vec.make (-.pl.dist *. pl.nx) (-.pl.dist *. pl.ny) (-.pl.dist *. pl.nz)) in
      max_abs [| q.x; q.y; q.z |]
  | None, Csg { members; _ } -> Array.fold_left (fun m o -> Float.max m o.mag) 0. members
  | None, (Sphere _ | Ellipsoid _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Box_trans _ | Cone _ | Disc _ | Torus _ | Glyph _) -> 0.

(* POV-Ray's box of a bounded shape (Compute_BBox, then Make_BBox or Make_BBox_from_min_max, which
   round the lower corner and the lengths to single precision): [| llx; lly; llz; lx; ly; lz |].
   A sphere's is its centre minus the radius and twice the radius; a triangle's its corners' extent
   widened by EPSILON; a mesh's its single-precision vertices' extent; a transformed sphere or
   mesh's the box of its untransformed box's mapped corners (Recompute_BBox; POV-Ray does that once
   per transformation, here once for their composition). *)
let rec pov_box shape =
  let of_min_max (lo : float array) (hi : float array) = Array.init 6 (fun i -> if i < 3 then f32 lo.(i) else f32 (hi.(i - 3) -. lo.(i - 3))) in
  let corners (b : float array) = ([| b.(0); b.(1); b.(2) |], [| b.(0) +. b.(3); b.(1) +. b.(4); b.(2) +. b.(5) |]) in
  let mapped tr b =
    let lo, hi = corners b in
    let m = Transform.bounds tr (Array.append lo hi) in
    of_min_max (Array.sub m 0 3) (Array.sub m 3 3)
  in
  let sphere_box (s : sphere) =
    let r = s.radius in
    [| f32 (s.cx -. r); f32 (s.cy -. r); f32 (s.cz -. r); f32 (2. *. r); f32 (2. *. r); f32 (2. *. r) |]
  in
  match shape with
  | Sphere s -> sphere_box s
  | Ellipsoid { sp; etr } -> mapped etr (sphere_box sp)
  | Plane _ | Plane_trans _ -> [||]
  | Triangle t | Smooth_triangle t ->
      let mn a b c = Float.min a (Float.min b c) -. epsilon and mx a b c = Float.max a (Float.max b c) +. epsilon in
      of_min_max [| mn t.x1 t.x2 t.x3; mn t.y1 t.y2 t.y3; mn t.z1 t.z2 t.z3 |] [| mx t.x1 t.x2 t.x3; mx t.y1 t.y2 t.y3; mx t.z1 t.z2 t.z3 |]
  | Mesh m ->
      let b = of_min_max (Array.sub (Mesh.extent m.mesh) 0 3) (Array.sub (Mesh.extent m.mesh) 3 3) in
      if m.moved then mapped m.tr b else b
  | Box b -> of_min_max [| b.x0; b.y0; b.z0 |] [| b.x1; b.y1; b.z1 |]
  | Box_trans { bx = b; btr } -> mapped btr (of_min_max [| b.x0; b.y0; b.z0 |] [| b.x1; b.y1; b.z1 |])
  | Cone c ->
      (* Cone::Compute_BBox: Make_BBox(−1, −1, dist, 2, 2, 1 − dist), then through Trans *)
      mapped c.ctr [| f32 (-1.); f32 (-1.); f32 c.dist; f32 2.; f32 2.; f32 (1. -. c.dist) |]
  | Disc d ->
      (* Disc::Compute_BBox: Make_BBox(−r, −r, −SMALL_TOLERANCE, 2r, 2r, 2·SMALL_TOLERANCE) *)
      let r = sqrt d.or2 in
      mapped d.dtr [| f32 (-.r); f32 (-.r); f32 (-.small_tolerance); f32 (2. *. r); f32 (2. *. r); f32 (2. *. small_tolerance) |]

  | Torus t ->
      (* Torus::Compute_BBox: Make_BBox of the torus-space box, then Recompute_BBox through its
         Trans, which every torus has (§15.5, §15.8) *)
      let b = Torus.box t in
      mapped t.tr (of_min_max (Array.sub b 0 3) (Array.sub b 3 3))
  | Glyph g ->
      (* TrueType::Compute_BBox: Make_BBox of the header's box, z from −1e-6 to depth + 1e-6,
         then Recompute_BBox through its whole Trans, at every transform (§15.9) *)
      let b = Glyph.box g in
      mapped g.tr (of_min_max (Array.sub b 0 3) (Array.sub b 3 3))
  | Csg { kind = Intersection; members = [| ({ shape = Sphere _ | Ellipsoid _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Box_trans _ | Cone _ | Disc _ | Torus _ | Glyph _; _ } as m) |]; _ }
    when m.inverted ->
      (* an inverted primitive written alone: POV-Ray's box is the primitive's own *)
      pov_box m.shape
  | Csg _ -> (
      (* CSG::Compute_BBox from the members' boxes, after the CSG's transforms (POV-Ray maps the
         box computed before them: a difference in equal-depth ties only) *)
      match bounds shape with None -> [||] | Some b -> of_min_max (Array.sub b 0 3) (Array.sub b 3 3))

(* Inside_BBox: whether [p] is in POV-Ray's box [b] of an object (faces included); an unbounded
   object's ([||]) holds every point. POV-Ray asks it before the object's own inside test when it
   fills the camera's interior list (§6.4), so a camera behind a disc is inside the disc's
   half-space only within the disc's thin box (§15.4). *)
let in_pov_box (b : float array) (p : Vec.t) =
  Array.length b = 0
  || not
       (p.x < b.(0) || p.y < b.(1) || p.z < b.(2) || p.x > b.(0) +. b.(3) || p.y > b.(1) +. b.(4) || p.z > b.(2) +. b.(5))

(* §6.4: of the top-level objects [holders], those whose bounding box and inside both hold [p], the
   last one first (the order of the interior list of a ray that starts at [p]). *)
let interiors_at (holders : obj array) stack p =
  Array.fold_left (fun acc o -> if in_pov_box o.pbox p && inside stack o.shape p then o.iid :: acc else acc) [] holders

(* §18.4: the top-level objects, in scene order, whose box an orthographic ray's origin can lie in:
   the origins lie on the screen, location + x0·right + y0·up with |x0|, |y0| ≤ ½ (twice that
   here, for antialiasing samples beyond the edge pixels), so the others are left out once, not
   per ray. Empty for a perspective camera, whose rays share one origin. *)
let screen_holders (cam : Scene.camera) (tops : obj list) =
  match cam.projection with
  | Perspective -> [||]
  | Orthographic ->
      let l = cam.location and r = cam.right and u = cam.up in
      let span a b = Float.abs a +. Float.abs b in
      let lo = [| l.x -. span r.x u.x; l.y -. span r.y u.y; l.z -. span r.z u.z |]
      and hi = [| l.x +. span r.x u.x; l.y +. span r.y u.y; l.z +. span r.z u.z |] in
      let meets (b : float array) =
        Array.length b = 0
        || not (b.(0) > hi.(0) || b.(1) > hi.(1) || b.(2) > hi.(2) || b.(0) +. b.(3) < lo.(0) || b.(1) +. b.(4) < lo.(1) || b.(2) +. b.(5) < lo.(2))
      in
      Array.of_list (List.filter (fun o -> meets o.pbox) tops)

let group objs =
  let unbounded = List.filter (fun o -> bounds o.shape = None) objs in
  let bounded = List.filter (fun o -> bounds o.shape <> None) objs in
  let boxes = Bvh.create_boxes (List.length bounded) in
  List.iteri (fun i o -> let b = Option.get (bounds o.shape) in Bvh.set_box boxes i b.(0) b.(1) b.(2) b.(3) b.(4) b.(5)) bounded;
  let bvh, perm = Bvh.renumber (Bvh.build boxes) in
  let objs = Array.of_list bounded in
  let bounded = Array.map (fun i -> objs.(i)) perm in
  (* each costly shape's own box, stored as the hierarchy stores a leaf's (widened, single
     precision), in leaf order *)
  let own = Bvh.create_boxes (Array.length bounded) in
  Array.iteri (fun i o -> let b = Option.get (bounds o.shape) in Bvh.set_box own i b.(0) b.(1) b.(2) b.(3) b.(4) b.(5)) bounded;
  let boxes = Array.make (6 * Array.length bounded) nan in
  Array.iteri
    (fun i o ->
      match o.shape with
      | Ellipsoid _ | Box_trans _ | Cone _ | Disc _ | Torus _ | Glyph _ -> for k = 0 to 5 do boxes.((6 * i) + k) <- Bigarray.Array1.get own ((6 * i) + k) done
      | Sphere _ | Plane _ | Plane_trans _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Csg _ -> ())
    bounded;
  let spheres = Array.make (4 * Array.length bounded) nan in
  Array.iteri
    (fun i o ->
      match o.shape with
      | Sphere s -> spheres.(4 * i) <- s.cx; spheres.((4 * i) + 1) <- s.cy; spheres.((4 * i) + 2) <- s.cz; spheres.((4 * i) + 3) <- s.r2
      | Ellipsoid _ | Plane _ | Plane_trans _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Box_trans _ | Cone _ | Disc _ | Torus _ | Glyph _ | Csg _ -> ())
    bounded;
  { unbounded = Array.of_list unbounded; bounded; bvh; spheres; boxes }

(* POV-Ray stores colours in single precision (§8.3); rounding the stored values the same way keeps
   results on the same side of the 8-bit rounding boundaries. *)
let rgb32 (c : Rgb.t) = Rgb.make (f32 c.r) (f32 c.g) (f32 c.b)

let colour32 (c : Colour.t) =
  { Colour.red = f32 c.red; green = f32 c.green; blue = f32 c.blue; filter = f32 c.filter; transmit = f32 c.transmit }

let reflection32 (r : Scene.reflection) =
  { r with rmin = rgb32 r.rmin; rmax = rgb32 r.rmax; falloff = f32 r.falloff; refl_metallic = f32 r.refl_metallic }

(* The fields of a surface that depend on its pigment colour [c] (single precision), the others
   taken from [base]. *)
let coloured ~legacy ~ambient_light (f : Scene.finish) base (c : Colour.t) =
  let colour = Colour.rgb c in
  (* §3.2: the legacy "att" formula applies below language version 3.70 *)
  let att =
    if legacy then 1. -. ((c.filter *. Rgb.max3 colour) +. c.transmit) else 1. -. c.filter -. c.transmit
  in
  (* §3.2, in single precision as POV-Ray sums it: ((C·ambient)·ambient_light)·att, then + (C·emission)·att *)
  let mul a b = f32 (a *. b) in
  let term c a l = mul (mul (mul c a) l) att in
  let emitted =
    Rgb.make
      (f32 (term colour.r f.ambient.r ambient_light.Rgb.r +. mul (mul colour.r f.emission.r) att))
      (f32 (term colour.g f.ambient.g ambient_light.g +. mul (mul colour.g f.emission.g) att))
      (f32 (term colour.b f.ambient.b ambient_light.b +. mul (mul colour.b f.emission.b) att))
  in
  {
    base with
    colour;
    att;
    emitted;
    filcol = Rgb.make (f32 (f32 (c.red *. c.filter) +. c.transmit)) (f32 (f32 (c.green *. c.filter) +. c.transmit)) (f32 (f32 (c.blue *. c.filter) +. c.transmit));
    transparent = c.filter <> 0. || c.transmit <> 0.;
  }

let surface ~legacy ~ambient_light (t : Scene.texture) =
  let f0 = t.finish in
  (* finish scalars are single precision too *)
  let f =
    {
      f0 with
      ambient = rgb32 f0.ambient;
      emission = rgb32 f0.emission;
      reflection = reflection32 f0.reflection;
      diffuse = f32 f0.diffuse;
      brilliance = f32 f0.brilliance;
      phong = f32 f0.phong;
      phong_size = f32 f0.phong_size;
      specular = f32 f0.specular;
      metallic = f32 f0.metallic;
    }
  in
  let ambient_light = rgb32 ambient_light in
  let r = f.reflection in
  let base =
    {
      colour = Rgb.black;
      att = 1.;
      emitted = Rgb.black;
      lit = f.diffuse <> 0. || f.phong <> 0. || f.specular <> 0.;
      diffuse = f.diffuse;
      brilliance = f.brilliance;
      phong = f.phong;
      phong_size = f.phong_size;
      specular = f.specular;
      spec_exp = (if f.roughness = 0. then 0. else f32 (1. /. f.roughness));
      metallic = f.metallic;
      refl = r;
      reflects = not (Rgb.is_zero r.rmin && Rgb.is_zero r.rmax);
      filcol = Rgb.black;
      transparent = false;
      conserve = f.conserve_energy;
      paint = Fixed;
    }
  in
  match t.pigment with
  | Solid c | Solid_placed { colour = c; _ } -> coloured ~legacy ~ambient_light f base (colour32 c)
  | Pattern p ->
      (* §17.1: the map colours are single precision already, and so is their blend *)
      let at x = coloured ~legacy ~ambient_light f base (Pigment.eval p x) in
      (* shading takes the surface at the point; [transparent] here says whether any colour of the
         pattern lets light through, which the shadow cache asks of a CSG's own texture *)
      { base with paint = Varying at; transparent = not (Pigment.opaque t.pigment) }

(* An object stops a shadow ray at once when none of its pigments lets light through (§4, §17.8). *)
let pigment_opaque (p : Scene.pigment) =
  match p with
  | Solid c | Solid_placed { colour = c; _ } ->
      let c = colour32 c in
      c.filter = 0. && c.transmit = 0.
  | Pattern _ -> Pigment.opaque p

(* Objects that share a texture (a declared one) share its compiled surface. *)
module Texture_memo = Hashtbl.Make (struct
  type t = Scene.texture

  let equal = ( == )
  let hash = Hashtbl.hash
end)

let scene (s : Scene.t) : Compiled.t =
  let legacy = s.version < 370 in
  let memo = Texture_memo.create 16 in
  let surface ~legacy ~ambient_light t =
    match Texture_memo.find_opt memo t with
    | Some sf -> sf
    | None ->
        let sf = surface ~legacy ~ambient_light t in
        Texture_memo.add memo t sf;
        sf
  in
  let surface_of (t : Scene.texture) = surface ~legacy ~ambient_light:s.ambient_light t in
  (* Objects are numbered in scene order, each CSG before its members (the numbering keeps the
     scene order of top-level objects, which decides ties without a bounding hierarchy). *)
  let next = ref 0 and built = ref [] in
  let rec build ~top ~iid ~inverted (o : Scene.obj) : obj option =
    let id = !next in
    let top = if top < 0 then id else top and iid = if iid < 0 then id else iid in
    let shape =
      match o.shape with
      | Csg { kind; members } ->
          incr next;
          let members =
            List.filter_map
              (fun (m : Scene.member) -> build ~top ~iid:(if m.own_interior then -1 else iid) ~inverted:m.inverted m.mobj)
              members
          in
          let members = Array.of_list members in
          Some (Csg { kind; members; cbox = pov_box (Csg { kind; members; cbox = [||] }) })
      | Sphere _ | Plane _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Cone _ | Disc _ | Torus _ | Glyph _ ->
          let sh = prim_of o.shape in
          if sh <> None then incr next;
          sh
    in
    match shape with
    | None -> None
    | Some shape ->
        let surf = surface_of o.texture in
        let face_surfs =
          match o.shape with
          | Mesh m -> Array.map surface_of m.textures
          | Sphere _ | Plane _ | Triangle _ | Smooth_triangle _ | Box _ | Cone _ | Disc _ | Torus _ | Glyph _ | Csg _ -> [||]
        in
        let opaque =
          match shape with
          | Csg { members; _ } -> Array.for_all (fun m -> m.opaque) members
          | Sphere _ | Ellipsoid _ | Plane _ | Plane_trans _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Box_trans _ | Cone _
          | Disc _ | Torus _ | Glyph _ -> (
              (* §17.8: opaque only if no colour the pigment can give is transparent *)
              pigment_opaque o.texture.pigment
              &&
              match o.shape with
              | Mesh m -> Array.for_all (fun (t : Scene.texture) -> pigment_opaque t.pigment) m.textures
              | Sphere _ | Plane _ | Triangle _ | Smooth_triangle _ | Box _ | Cone _ | Disc _ | Torus _ | Glyph _ | Csg _ -> true)
        in
        let ob =
          {
            id;
            iid;
            top;
            inverted;
            shape;
            surf;
            face_surfs;
            ior = f32 o.interior.ior;
            fade_distance = f32 o.interior.fade_distance;
            fade_power = f32 o.interior.fade_power;
            fade_colour = rgb32 o.interior.fade_colour;
            old_refract = f32 o.texture.finish.refraction;
            opaque;
            mag = magnitude shape;
            pbox = pov_box shape;
            double_illuminate = o.double_illuminate;
          }
        in
        built := ob :: !built;
        Some ob
  in
  let visible = List.filter_map (fun (o : Scene.obj) -> Option.map (fun ob -> (o, ob)) (build ~top:(-1) ~iid:(-1) ~inverted:false o)) s.objects in
  let objects = Array.of_list (List.sort (fun a b -> compare a.id b.id) !built) in
  let tops = List.map snd visible in
  let casts = List.filter_map (fun ((o : Scene.obj), ob) -> if o.no_shadow then None else Some ob) visible in
  let occluders = casts in
  let shadow_mode =
    if occluders = [] then No_occluders
    else if List.for_all (fun o -> o.opaque) occluders then Any_hit
    else Filtered
  in
  let stack = Array.make 512 0. in
  let lights =
    Array.of_list
      (List.map
         (fun (l : Scene.light) ->
           (* §14.8: normalize(point_at − centre), left as it is when shorter than EPSILON *)
           let dir =
             let v = Vec.sub l.point_at l.position in
             let len = Vec.length v in
             if len > epsilon then Vec.make (v.x /. len) (v.y /. len) (v.z /. len) else v
           in
           {
             lx = l.position.x;
             ly = l.position.y;
             lz = l.position.z;
             lcolour = rgb32 l.colour;
             shadowless = l.shadowless;
             fade = l.fade_power > 0. && Float.abs l.fade_distance > epsilon;
             lfade_distance = l.fade_distance;
             lfade_power = l.fade_power;
             spread =
               (match l.kind with
               | Point_light -> Everywhere
               | Spotlight -> Spot { radius_cos = l.radius; falloff_cos = l.falloff; tightness = l.tightness }
               | Cylinder_light -> Beam { beam_radius = l.radius; beam_falloff = l.falloff; beam_tightness = l.tightness });
             parallel = l.parallel;
             dx = dir.x;
             dy = dir.y;
             dz = dir.z;
           })
         s.lights)
  in
  (* §6.4: the camera ray starts inside every object that contains the camera location; the list
     is kept with the last entered first. *)
  let all = group tops in
  (* §16.6: image rays never meet no_image objects, reflection rays never meet no_reflection ones
     (tested on top-level objects, §16.4); a scene without those flags searches one group for every
     ray *)
  let without keep =
    if List.for_all (fun ((o : Scene.obj), _) -> keep o) visible then all
    else group (List.filter_map (fun ((o : Scene.obj), ob) -> if keep o then Some ob else None) visible)
  in
  let cam = s.camera.location in
  (* a light's looks_like shape belongs to the light's top-level object (§19.2) *)
  let bounding = List.length (List.filter (fun (o : Scene.obj) -> not o.looks_like) s.objects) + List.length s.lights >= 3 in
  (* the list holds interiors: a CSG's members share theirs (§16.5) *)
  let holds o = in_pov_box o.pbox cam && inside stack o.shape cam in
  let holders = List.filter holds tops in
  let start_interiors =
    match holders with
    | [] | [ _ ] -> List.map (fun o -> o.iid) holders
    | _ :: _ :: _ ->
        (* with its bounding tree POV-Ray meets the objects in the tree's order, else in scene
           order; the order matters only when the camera is inside two or more, and only then is
           the tree built *)
        let candidates =
          if bounding then
            let finite, infinite = List.partition (fun o -> Array.length o.pbox > 0) tops in
            Slab_tree.walk (Slab_tree.build (List.map (fun o -> (o.id, o.pbox)) finite) (List.map (fun o -> o.id) infinite)) (fun b ->
                in_pov_box b cam)
          else List.map (fun o -> o.id) holders
        in
        List.fold_left (fun acc id -> if holds objects.(id) then objects.(id).iid :: acc else acc) [] candidates
  in
  {
    objects;
    all;
    seen = without (fun o -> not o.no_image);
    mirrored = without (fun o -> not o.no_reflection);
    occluders = (if List.length occluders = List.length tops then all else group occluders);
    shadow_mode;
    lights;
    background = s.background;
    sky = s.sky;
    max_trace_level = s.max_trace_level;
    adc_bailout = s.adc_bailout;
    legacy;
    camera = s.camera;
    start_interiors;
    screen_holders = screen_holders s.camera tops;
    bounding;
  }
