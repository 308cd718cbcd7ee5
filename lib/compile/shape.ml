(* The dispatch of every shape operation to the shape's module: one direct match per operation. *)

open Compiled

let finite (t : Transform.t) =
  List.for_all Float.is_finite
    [ t.m00; t.m01; t.m02; t.m10; t.m11; t.m12; t.m20; t.m21; t.m22; t.m30; t.m31; t.m32;
      t.i00; t.i01; t.i02; t.i10; t.i11; t.i12; t.i20; t.i21; t.i22; t.i30; t.i31; t.i32 ]

let compile ~iso_slot (s : Scene.shape) =
  match s with
  | Sphere { centre; radius; trans = None; uv_trans = None } -> Some (Sphere (Sphere.make centre radius))
  | Sphere { centre; radius; trans = None; uv_trans = Some u } -> Some (Sphere_placed (Sphere.placed (Sphere.make centre radius) u))
  | Sphere { centre; radius; trans = Some etr; uv_trans } -> Some (Ellipsoid (Sphere.ellipsoid (Sphere.make centre radius) etr uv_trans))
  | Plane { normal; offset; trans = None } -> Some (Plane (Plane.make normal offset))
  | Plane { normal; offset; trans = Some ptr } -> Some (Plane_trans (Plane.moved normal offset ptr))
  | Triangle { p1; p2; p3 } -> Option.map (fun t -> Triangle t) (Triangle.flat p1 p2 p3)
  | Smooth_triangle { p1; n1; p2; n2; p3; n3 } -> (
      match Triangle.smooth p1 n1 p2 n2 p3 n3 with Some (Ok t) -> Some (Smooth_triangle t) | None | Some (Error ()) -> None)
  | Mesh { mesh; trans; _ } -> Some (Mesh (Mesh.place mesh trans))
  | Box { lo; hi; trans } -> (
      let bx = Box.make lo hi in
      match trans with None -> Some (Box bx) | Some btr -> Some (Box_trans { bx; btr }))
  | Cone { cylinder; dist; closed; trans; _ } ->
      (* a cylinder of radius 0 has no inverse transform: POV-Ray never hits it *)
      if finite trans then Some (Cone { ctr = trans; dist; cyl = cylinder; closed }) else None
  | Disc { normal; radius; hole; trans; _ } -> if finite trans then Some (Disc (Disc.make ~normal ~radius ~hole trans)) else None
  | Torus { major; minor; sturm; trans } -> Some (Torus { Torus.major; minor; sturm; tr = trans })
  | Glyph { outline; depth; trans } -> if finite trans then Some (Glyph { Glyph.outline; depth; tr = trans }) else None
  | Polygon p -> Some (Polygon p)
  | Quadric q -> Some (Quadric q)
  | Blob { blob; _ } -> Some (Blob (Blob.compile blob))
  | Height_field { field; trans } -> if finite trans then Some (Height_field { Hfield.field; tr = trans }) else None
  | Superellipsoid q -> Some (Superellipsoid q)
  | Ovus v -> Some (Ovus v)
  | Sphere_sweep s -> Some (Sphere_sweep (Sphere_sweep.compile s))
  | Prism p -> Some (Prism p)
  | Lathe l -> Some (Lathe l)
  | Sor s -> Some (Sor s)
  | Julia f -> Some (Julia f)
  | Isosurface i -> Some (Isosurface (Isosurface.compile ~slot:iso_slot i))
  | Parametric m -> Some (Parametric m)
  | Bicubic { patch_type; u_steps; v_steps; flatness; points; uv_vectors } ->
      Some (Bicubic (Bezier.make ~patch_type ~u_steps ~v_steps ~flatness ~st:uv_vectors points))
  | Poly p -> Some (Poly p)
  | Csg _ -> None

let traits = function
  | Sphere _ | Sphere_placed _ -> Sphere.traits
  | Ellipsoid _ -> Sphere.ellipsoid_traits
  | Plane _ | Plane_trans _ -> Plane.traits
  | Triangle _ -> Triangle.traits
  | Smooth_triangle _ -> Triangle.smooth_traits
  | Mesh _ -> Mesh.traits
  | Box _ -> Box.traits
  | Box_trans _ -> Box.moved_traits
  | Cone _ -> Cone.traits
  | Disc _ -> Disc.traits
  | Torus _ -> Torus.traits
  | Csg _ -> Shape_kind.csg
  | Glyph _ -> Glyph.traits
  | Polygon _ -> Polygon.traits
  | Quadric _ -> Quadric.traits
  | Blob _ -> Blob.traits
  | Height_field _ -> Hfield.traits
  | Superellipsoid _ -> Superellipsoid.traits
  | Ovus _ -> Ovus.traits
  | Sphere_sweep _ -> Sphere_sweep.traits
  | Prism _ -> Prism.traits
  | Lathe _ -> Lathe.traits
  | Sor _ -> Sor.traits
  | Isosurface _ -> Isosurface.traits
  | Julia _ -> Julia.traits
  | Parametric _ -> Parametric.traits
  | Bicubic _ -> Bezier.traits
  | Poly _ -> Poly.traits

(* a primitive crossed once at most *)
let[@inline] one_hit w t id o d lo n = if t < infinity then Scratch.push_ray w n lo t (-1) id o d else n

let rec depth w shape o d lo =
  match shape with
  | Csg c -> Csg.depth ~all_hits ~inside:inside_member w c o d lo
  | Sphere s | Sphere_placed { ps = s; _ } -> Sphere.depth w s o d lo
  | Ellipsoid e -> Sphere.ellipsoid_depth w e o d lo
  | Plane p -> Plane.depth w p o d lo
  | Plane_trans p -> Plane.moved_depth w p o d lo
  | Box b -> Box.depth w b o d lo
  | Box_trans b -> Box.moved_depth w b o d lo
  | Cone c -> Cone.depth w c o d lo
  | Disc dc -> Disc.depth w dc o d lo
  | Torus t -> Torus.depth w t o d lo
  | Glyph g -> Glyph.depth w g o d lo
  | Triangle t | Smooth_triangle t -> Triangle.depth w t o d lo
  | Mesh m -> Mesh.depth w m o d lo
  | Polygon p -> Polygon.depth w p o d lo
  | Quadric q -> Quadric.depth w q o d lo
  | Blob b -> Blob_ray.depth w b o d lo
  | Height_field h -> Hfield.depth w h o d lo
  | Superellipsoid q -> Superellipsoid.depth w q o d lo
  | Ovus v -> Ovus.depth w v o d lo
  | Sphere_sweep s -> Sphere_sweep.depth w s o d lo
  | Prism p -> Prism.depth w p o d lo
  | Lathe l -> Lathe.depth w l o d lo
  | Sor s -> Sor.depth w s o d lo
  | Julia f -> Julia.depth w f o d lo
  | Isosurface i -> Isosurface.depth w i o d lo
  | Parametric m -> Parametric.depth w m o d lo
  | Bicubic b -> Bezier.depth w b o d lo
  | Poly p -> Poly.depth w p o d lo

and all_hits w (m : member) o d lo n =
  let id = m.id in
  match m.shape with
  | Csg c -> Csg.hits ~all_hits ~inside:inside_member w c o d lo n
  | Sphere s | Sphere_placed { ps = s; _ } -> Sphere.hits w s id o d lo n
  | Ellipsoid e -> Sphere.ellipsoid_hits w e id o d lo n
  | Plane p -> one_hit w (Plane.depth w p o d lo) id o d lo n
  | Plane_trans p -> one_hit w (Plane.moved_depth w p o d lo) id o d lo n
  | Triangle t | Smooth_triangle t -> Triangle.hits w t id o d lo n
  | Box b -> Box.hits w b id o d lo n
  | Box_trans b -> Box.moved_hits w b id o d lo n
  | Mesh m -> Mesh.hits w m id o d lo n
  | Cone c -> Cone.hits w c id o d lo n
  | Disc dc -> Disc.hits w dc id o d lo n
  | Torus t -> Torus.hits w t id o d lo n
  | Glyph g -> Glyph.hits w g id o d lo n
  | Polygon p -> Polygon.hits w p id o d lo n
  | Quadric q -> Quadric.hits w q id o d lo n
  | Blob b -> Blob_ray.hits w b id o d lo n
  | Height_field h -> Hfield.hits w h id o d lo n
  | Superellipsoid q -> Superellipsoid.hits w q id o d lo n
  | Ovus v -> Ovus.hits w v id o d lo n
  | Sphere_sweep s -> Sphere_sweep.hits w s id o d lo n
  | Prism p -> Prism.hits w p id o d lo n
  | Lathe l -> Lathe.hits w l id o d lo n
  | Sor s -> Sor.hits w s id o d lo n
  | Julia f -> Julia.hits w f id o d lo n
  | Isosurface i -> Isosurface.hits w i id o d lo n
  | Parametric m -> Parametric.hits w m id o d lo n
  | Bicubic b -> Bezier.hits w b id o d lo n
  | Poly p -> Poly.hits w p id o d lo n

and inside stack shape p =
  match shape with
  | Csg c -> Csg.inside ~inside:inside_member stack c p
  | Cone c -> Cone.inside c p
  | Disc d -> Disc.inside d p
  | Box b -> Box.inside b p
  | Box_trans b -> Box.moved_inside b p
  | Torus t -> Torus.inside t p
  | Glyph g -> Glyph.inside g p
  | Sphere s | Sphere_placed { ps = s; _ } -> Sphere.inside s p
  | Ellipsoid e -> Sphere.ellipsoid_inside e p
  | Plane pl -> Plane.inside pl p
  | Plane_trans pl -> Plane.moved_inside pl p
  | Triangle _ | Smooth_triangle _ -> false
  | Mesh m -> Mesh.placed_inside stack m p
  | Polygon pg -> Polygon.inside pg p
  | Quadric q -> Quadric.inside q p
  | Blob b -> Blob.inside b p
  | Height_field h -> Hfield.inside h p
  | Superellipsoid q -> Superellipsoid.inside q p
  | Ovus v -> Ovus.inside v p
  | Sphere_sweep s -> Sphere_sweep.inside s p
  | Prism pr -> Prism.inside pr p
  | Lathe l -> Lathe.inside l p
  | Sor s -> Sor.inside s p
  | Julia f -> Julia.inside stack f p
  | Isosurface i -> Isosurface.inside i p
  | Bicubic _ | Parametric _ -> false (* Parametric::Inside is always false *)
  | Poly pl -> Poly.inside pl p

and inside_member stack (m : member) p =
  (* a member's Inside is negated when it is inverted, unless its own Inside already holds the
     inversion (a morphed CSG, a quadric's negated coefficients, a julia fractal's flag: §16.3) *)
  if (traits m.shape).inside_holds_inverse then inside stack m.shape p else inside stack m.shape p <> m.inverted

(* a shape whose box test POV-Ray's Intersect_BBox always passes, and such a shape under
   clipped_by or bounded_by: the wrappers are its *)
let rec box_test_free = function
  | Csg { kind = Clipped | Bounded | Boxed; members; _ } when Array.length members > 0 -> box_test_free members.(0).shape
  | shape -> (traits shape).box_test_free

let cached_depth w shape o d lo hi =
  match shape with
  | Csg c when box_test_free shape -> Csg.depth_unboxed ~all_hits ~inside:inside_member w c o d lo
  | Isosurface i when not (Pov_box.met i.box o d ~within:hi) -> infinity (* FindIntersection's box test *)
  | _ -> depth w shape o d lo

let hit_object (w : Scratch.t) ob = if Csg.is_csg ob.shape then w.leaf else ob.id

let normal w obj part p =
  match obj.shape with
  | Cone c -> Cone.normal c part p
  | Disc dc -> Disc.normal dc
  | Csg _ -> Vec.make 0. 0. 1. (* never hit: the member primitive is *)
  | Box _ -> Box.side_normal part
  | Box_trans b -> Box.moved_normal b part
  | Torus t -> Torus.normal t p
  | Glyph g -> Glyph.normal g part
  | Sphere s | Sphere_placed { ps = s; _ } -> Sphere.normal s p
  | Ellipsoid e -> Sphere.ellipsoid_normal e p
  | Plane pl -> Vec.make pl.nx pl.ny pl.nz
  | Plane_trans { pnormal; _ } -> pnormal
  | Triangle t -> Triangle.flat_normal t
  | Smooth_triangle t -> Triangle.smooth_normal t p
  | Mesh m -> Mesh.placed_normal m part p
  | Polygon pg -> Polygon.normal pg p
  | Quadric q -> Quadric.normal q p
  | Blob b -> Blob.normal b p
  | Height_field h -> Hfield.normal w h part p
  | Superellipsoid q -> Superellipsoid.normal q p
  | Ovus v -> Ovus.normal v part p
  | Sphere_sweep s -> Sphere_sweep.normal s part p
  | Prism pr -> Prism.normal pr part p
  | Lathe l -> Lathe.normal l part p
  | Sor s -> Sor.normal s part p
  | Julia f -> Julia.normal f p
  | Isosurface i -> Isosurface.normal i part p
  | Bicubic _ | Parametric _ -> Vec.make 1. 0. 0. (* its normal is the crossing's: hit_normal *)
  | Poly pl -> Poly.normal pl p

(* the shapes whose normal is blended from vertex normals; any other's is its surface's own *)
let geometric_normal w obj part p =
  match obj.shape with
  | Smooth_triangle t -> Triangle.flat_normal t
  | Mesh m -> Mesh.placed_face_normal m part
  | _ -> normal w obj part p

let hit_normal (w : Scratch.t) obj part c p =
  match obj.shape with
  | Julia _ | Bicubic _ -> Crossing.normal c
  | Parametric m -> Parametric.hit_normal m c
  | Sphere _ | Sphere_placed _ | Ellipsoid _ | Plane _ | Plane_trans _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Box_trans _ | Cone _ | Disc _
  | Torus _ | Glyph _ | Polygon _ | Quadric _ | Csg _ | Poly _ | Blob _ | Height_field _ | Superellipsoid _ | Ovus _ | Sphere_sweep _ | Prism _ | Lathe _ | Sor _
  | Isosurface _ ->
      normal w obj part p

let hit_point w obj c o depth d =
  match obj.shape with
  | Poly pl -> Poly.hit_point w pl o d depth
  | Julia _ -> Crossing.point c
  | Sphere _ | Sphere_placed _ | Ellipsoid _ | Plane _ | Plane_trans _ | Triangle _ | Smooth_triangle _ | Mesh _ | Box _ | Box_trans _ | Cone _ | Disc _ | Torus _ | Glyph _ | Polygon _ | Quadric _
  | Isosurface _ | Parametric _ | Blob _ | Height_field _ | Superellipsoid _ | Ovus _ | Sphere_sweep _ | Prism _ | Lathe _ | Sor _ | Bicubic _ | Csg _ ->
      Vec.madd o depth d

let refine obj p =
  match obj.shape with
  | Sphere s | Sphere_placed { ps = s; _ } -> Sphere.refine s p
  | Ellipsoid e -> Sphere.ellipsoid_refine e p
  | _ -> p (* no other shape puts a point back on its surface *)

(* Every shape's UVCoord in POV-Ray 3.7: spheres, boxes, tori and meshes have their own; every
   other shape (planes, triangles, cones and cylinders, discs, polygons, quadrics, letters) the
   default ObjectBase::UVCoord, the world point's x and y as they are *)
let uv obj part c (p : Vec.t) =
  match obj.shape with
  | Bicubic _ | Parametric _ -> Crossing.uv c
  | Sphere s -> Sphere.uv s p
  | Sphere_placed s -> Sphere.placed_uv s p
  | Ellipsoid e -> Sphere.ellipsoid_uv e p
  | Box b -> Box.uv b part p
  | Box_trans b -> Box.moved_uv b part p
  | Torus t -> Torus.uv t p
  | Mesh m -> Mesh.placed_uv m part p
  | Ovus v -> Ovus.uv v p
  | Lathe l -> Lathe.uv l part p
  | Sor s -> Sor.uv s part p
  | Plane _ | Plane_trans _ | Triangle _ | Smooth_triangle _ | Cone _ | Disc _ | Glyph _ | Polygon _ | Quadric _ | Poly _ | Blob _ | Height_field _ | Superellipsoid _ | Sphere_sweep _ | Prism _
  | Julia _ | Isosurface _ | Csg _ ->
      Vec.make p.x p.y 0.

let rec bounds = function
  | Csg c -> Csg.bounds ~bounds c
  | Sphere s | Sphere_placed { ps = s; _ } -> Some (Sphere.bounds s)
  | Ellipsoid e -> Some (Sphere.ellipsoid_bounds e)
  | Plane _ | Plane_trans _ -> None
  | Triangle t | Smooth_triangle t -> Some (Triangle.bounds t)
  | Mesh m -> Some (Mesh.placed_bounds m)
  | Box b -> Some (Box.bounds b)
  | Box_trans b -> Some (Box.moved_bounds b)
  | Cone c -> Some (Cone.bounds c)
  | Disc d -> Some (Disc.bounds d)
  | Torus t -> Some (Torus.bounds t)
  | Glyph g -> Some (Glyph.bounds g)
  | Polygon p -> Polygon.bounds p
  | Quadric q -> Quadric.bounds q
  | Blob b -> Some (Blob.bounds b)
  | Height_field h -> Some (Hfield.bounds h)
  | Superellipsoid q -> Some (Superellipsoid.bounds q)
  | Ovus v -> Some (Ovus.bounds v)
  | Sphere_sweep s -> Some (Sphere_sweep.bounds s)
  | Prism p -> Some (Prism.bounds p)
  | Lathe l -> Some (Lathe.bounds l)
  | Sor s -> Some (Sor.bounds s)
  | Julia f -> Some (Julia.bounds f)
  | Isosurface i -> Some (Isosurface.bounds i.iso)
  | Parametric m -> Some (Parametric.bounds m)
  | Bicubic b -> Some (Bezier.bounds b)
  | Poly _ -> None (* POV-Ray's BOUND_HUGE box: an infinite object *)

let magnitude shape =
  let max_abs a = Array.fold_left (fun m x -> Float.max m (Float.abs x)) 0. a in
  match (bounds shape, shape) with
  | Some b, _ -> max_abs b
  | None, Plane p -> Plane.magnitude p
  | None, Plane_trans p -> Plane.moved_magnitude p
  | None, Csg c -> Csg.magnitude c
  | _, Polygon p -> Polygon.magnitude p
  | _, Quadric q -> Quadric.magnitude q
  | None, _ -> 0. (* a poly: POV-Ray's unbounded box tells nothing *)

let rec pov_box shape =
  match shape with
  | Sphere s | Sphere_placed { ps = s; _ } -> Sphere.pov_box s
  | Ellipsoid e -> Sphere.ellipsoid_pov_box e
  | Plane _ | Plane_trans _ -> [||]
  | Triangle t | Smooth_triangle t -> Triangle.pov_box t
  | Mesh m -> Mesh.placed_pov_box m
  | Box b -> Box.pov_box b
  | Box_trans b -> Box.moved_pov_box b
  | Cone c -> Cone.pov_box c
  | Disc d -> Disc.pov_box d
  | Torus t -> Torus.pov_box t
  | Glyph g -> Glyph.pov_box g
  | Polygon p -> Polygon.pov_box p
  | Quadric q -> Quadric.pov_box q
  | Blob b -> Blob.pov_box b
  | Height_field h -> Hfield.pov_box h
  | Superellipsoid q -> Superellipsoid.pov_box q
  | Ovus v -> Ovus.pov_box v
  | Sphere_sweep s -> Sphere_sweep.pov_box s
  | Prism p -> Prism.pov_box p
  | Lathe l -> Lathe.pov_box l
  | Sor s -> Sor.pov_box s
  | Julia f -> Julia.pov_box f
  | Isosurface i -> Isosurface.pov_box i.iso
  | Parametric m -> Parametric.pov_box m
  | Bicubic b -> Bezier.pov_box b
  | Poly _ -> [||]
  | Csg c -> Csg.pov_box ~pov_box c

let costly shape = (traits shape).costly

let as_sphere = function Sphere s | Sphere_placed { ps = s; _ } -> Some s | _ -> None

let face_texture obj part =
  match obj.shape with
  | Mesh m when part >= 0 -> Mesh.texture m.mesh part
  | _ -> -1 (* only a mesh's faces have textures of their own *)
