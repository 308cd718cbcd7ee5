(* Moving shapes, and the whole scene. What one object modifier does to a shape (docs/povray-rules.md §14.4), following the shapes' Translate,
   Rotate, Scale and Transform methods in POV-Ray (shape/spheres.cpp, planes.cpp, triangle.cpp,
   mesh.cpp) down to the operation order, since a baked parameter is only bit-exact if it is
   computed the same way. *)

type op = Translate of Vec.t | Rotate of Vec.t | Scale of Vec.t | Transform of Transform.t

let op_transform = function
  | Translate v -> Transform.translate v
  | Rotate a -> Transform.rotate a
  | Scale s -> Transform.scale s
  | Transform t -> t

(* Create_Transform() then Compose_Transforms: a shape's first transform is composed onto the
   identity, exactly as POV-Ray does it. *)
let attach trans op =
  match trans with
  | None -> Transform.compose Transform.identity (op_transform op)
  | Some t -> Transform.compose t (op_transform op)

(* Triangle::Compute_Triangle on the current corners, as POV-Ray runs it after parsing and after
   every modifier: None when the triangle has no area (it is then flagged DEGENERATE and ignores
   all later modifiers), else the unit normal and whether P1 and P2 are swapped. The normal is
   scaled by the reciprocal of its length (VInverseScaleEq). *)
let settle (p1 : Vec.t) (p2 : Vec.t) (p3 : Vec.t) =
  let n = Vec.cross (Vec.sub p1 p2) (Vec.sub p3 p2) in
  let len = Vec.length n in
  if len = 0. then None
  else
    let k = 1. /. len in
    let n = Vec.make (n.x *. k) (n.y *. k) (n.z *. k) in
    let axis = Triangle.max3_coordinate (Float.abs n.x) (Float.abs n.y) (Float.abs n.z) in
    Some (n, Triangle.needs_swap axis p1 p2 p3)

(* SmoothTriangle::Scale: normals divided by the scale and renormalised (VScaleEq by 1/length). *)
let scale_normal (n : Vec.t) (s : Vec.t) =
  let n = Vec.make (n.x /. s.x) (n.y /. s.y) (n.z /. s.z) in
  let k = 1. /. Vec.length n in
  Vec.make (n.x *. k) (n.y *. k) (n.z *. k)

let move_point op (p : Vec.t) =
  match op with
  | Translate v -> Vec.add p v
  | Scale s -> Vec.mul p s
  | Rotate _ | Transform _ -> Transform.point (op_transform op) p

(* Transform_Tpattern: a transform composes into the head of the warp list when that is a
   transform, else becomes the new head (created on the identity first) *)
let transform_warps (ws : Scene.warp list) t : Scene.warp list =
  match ws with
  | Transform_warp m :: rest -> Transform_warp (Transform.compose m t) :: rest
  | _ -> Transform_warp (Transform.compose Transform.identity t) :: ws

let transform_pigment (p : Scene.pigment) t : Scene.pigment =
  (* Transform_Tpattern: composed into the head transform, created on the identity first; a plain
     colour keeps its transform too, for an edit that gives it a pattern (§17.9). A uv-mapped
     pigment is unchanged: POV-Ray composes the transform into the UV_MAP_PATTERN wrapper, whose
     warps its evaluation never applies *)
  match p with
  | Solid colour -> Solid_placed { colour; strans = Transform.compose Transform.identity t }
  | Solid_placed { colour; strans } -> Solid_placed { colour; strans = Transform.compose strans t }
  | Pattern { uv_mapping = true; _ } -> p
  | Pattern pp -> Pattern { pp with warps = transform_warps pp.warps t }

let transform_normal (n : Scene.normal) t : Scene.normal =
  (* as [transform_pigment]: a uv-mapped normal's wrapper takes the transform and never uses it *)
  if n.nuv_mapping then n else { n with nwarps = transform_warps n.nwarps t }

(* §14.7: a texture attached before a transform moves with the object *)
let transform_layer (t : Scene.layer) m =
  let normal = match t.normal with None -> None | Some n -> Some (transform_normal n m) in
  { t with pigment = transform_pigment t.pigment m; normal }

(* Transform_Textures: every layer's pigment and normal; a patterned texture's own pattern only,
   its entries living in the space the pattern sees *)
let transform_texture (t : Scene.texture) m : Scene.texture =
  match t with
  | Layers ls -> Layers (List.map (fun l -> transform_layer l m) ls)
  | Texture_pattern p -> Texture_pattern { p with tpat = { p.tpat with warps = transform_warps p.tpat.warps m } }
  | Cutaway -> Cutaway
  | Uv_mapped u -> Uv_mapped { u with uwarps = transform_warps u.uwarps m }
  | Material_map mm -> Material_map { mm with mwarps = transform_warps mm.mwarps m }

let layer t op = transform_layer t (op_transform op)
let texture t op = transform_texture t (op_transform op)

(* A CSG's box as one modifier maps it (Recompute_BBox): its corners' extent; an unbounded box
   stays unbounded *)
let csg_box box op = Option.map (fun b -> if Array.length b = 0 then b else Pov_box.mapped (op_transform op) b) box

let rec shape (s : Scene.shape) op : Scene.shape =
  match s with
  | Sphere { centre; radius; trans = None; uv_trans } -> (
      (* §2.2, Sphere::Translate/Rotate/Scale/Transform; Translate_Object and the others compose
         every modifier into UV_Trans as well *)
      let uv_trans = Some (attach uv_trans op) in
      match op with
      | Translate v -> Sphere { centre = Vec.add centre v; radius; trans = None; uv_trans }
      | Rotate _ -> Sphere { centre = Transform.point (op_transform op) centre; radius; trans = None; uv_trans }
      | Scale v when v.x = v.y && v.x = v.z ->
          Sphere { centre = Vec.scale v.x centre; radius = radius *. Float.abs v.x; trans = None; uv_trans }
      | Scale _ | Transform _ ->
          (* an ellipsoid: the sphere as it stands, in object space, mapped by a new transform *)
          Sphere { centre; radius; trans = Some (attach None op); uv_trans })
  | Sphere { centre; radius; trans = Some _ as trans; uv_trans } ->
      Sphere { centre; radius; trans = Some (attach trans op); uv_trans = Some (attach uv_trans op) }
  | Plane { normal; offset; trans = None } -> (
      (* §2.3, Plane::Translate/Rotate/Scale; offset is −Distance *)
      match op with
      | Translate v -> Plane { normal; offset = offset +. Vec.dot normal v; trans = None }
      | Rotate _ -> Plane { normal = Transform.direction (op_transform op) normal; offset; trans = None }
      | Scale v ->
          let n = Vec.make (normal.x /. v.x) (normal.y /. v.y) (normal.z /. v.z) in
          let len = Vec.length n in
          let k = 1. /. len in
          Plane { normal = Vec.make (n.x *. k) (n.y *. k) (n.z *. k); offset = offset /. len; trans = None }
      | Transform _ -> Plane { normal; offset; trans = Some (attach None op) })
  | Plane { normal; offset; trans = Some _ as trans } -> Plane { normal; offset; trans = Some (attach trans op) }
  | Triangle { p1; p2; p3 } -> (
      (* §2.4, Triangle::Translate/Rotate/Scale/Transform: the corners move, then the set-up runs
         again; the swap of the previous set-up is applied first *)
      match settle p1 p2 p3 with
      | None -> s
      | Some (_, swap) ->
          let p1, p2 = if swap then (p2, p1) else (p1, p2) in
          Triangle { p1 = move_point op p1; p2 = move_point op p2; p3 = move_point op p3 })
  | Smooth_triangle { p1; n1; p2; n2; p3; n3 } -> (
      (* §2.5, SmoothTriangle::…: normals by MTransNormal (not renormalised) except under scale;
         a triangle whose vertex normals straddle its face is DEGENERATE and stays as it is *)
      match settle p1 p2 p3 with
      | None -> s
      | Some (n, swap) ->
          let a = Vec.dot n n1 and b = Vec.dot n n2 and c = Vec.dot n n3 in
          if not ((a < 0. && b < 0. && c < 0.) || (a > 0. && b > 0. && c > 0.)) then s
          else
            let p1, p2, n1, n2 = if swap then (p2, p1, n2, n1) else (p1, p2, n1, n2) in
            let mp = move_point op in
            let mn (n : Vec.t) =
              match op with
              | Translate _ -> n
              | Scale v -> scale_normal n v
              | Rotate _ | Transform _ -> Transform.normal (op_transform op) n
            in
            Smooth_triangle { p1 = mp p1; n1 = mn n1; p2 = mp p2; n2 = mn n2; p3 = mp p3; n3 = mn n3 })
  | Box { lo; hi; trans = None } -> (
      (* §15.1, Box::Translate/Scale: translate and scale move the corners (re-sorted per axis
         after a scale); rotate and matrix attach a transform *)
      match op with
      | Translate v -> Box { lo = Vec.add lo v; hi = Vec.add hi v; trans = None }
      | Scale v ->
          let a = Vec.mul lo v and b = Vec.mul hi v in
          (* swapped only where the lower corner came out above the upper one *)
          let lo_of p q = if p > q then q else p and hi_of p q = if p > q then p else q in
          let lo = Vec.make (lo_of a.x b.x) (lo_of a.y b.y) (lo_of a.z b.z) in
          let hi = Vec.make (hi_of a.x b.x) (hi_of a.y b.y) (hi_of a.z b.z) in
          Box { lo; hi; trans = None }
      | Rotate _ | Transform _ -> Box { lo; hi; trans = Some (attach None op) })
  | Box { lo; hi; trans = Some _ as trans } -> Box { lo; hi; trans = Some (attach trans op) }
  | Torus t ->
      (* §15.5, Torus::Translate/Rotate/Scale all call Transform: composed into its Trans *)
      Torus { t with trans = attach (Some t.trans) op }
  | Glyph g ->
      (* §15.9, TrueType::Translate/Rotate/Scale all call Transform: composed into its Trans *)
      Glyph { g with trans = attach (Some g.trans) op }
  | Mesh { mesh; trans; textures } ->
      (* §2.6, Mesh::Translate/Rotate/Scale all call Transform *)
      Mesh { mesh; trans = Some (attach trans op); textures = Array.map (fun t -> texture t op) textures }
  | Cone c ->
      (* §14.4, Cone::Translate/Rotate/Scale/Transform: every modifier is composed into Trans *)
      Cone { c with trans = attach (Some c.trans) op }
  | Disc d ->
      (* §15.4, Disc::Transform: the normal by the inverse transpose, normalised, at every step *)
      let t = op_transform op in
      Disc { d with normal = Transform.normalize (Transform.normal t d.normal); trans = Transform.compose d.trans t }
  | Polygon p ->
      (* §15.7, Polygon::Translate/Rotate/Scale all call Transform: composed into its Trans *)
      Polygon (Polygon.transform p (op_transform op))
  | Height_field h ->
      (* HField::Translate/Rotate/Scale all call Transform: composed into its Trans *)
      Height_field { h with trans = attach (Some h.trans) op }
  | Poly p ->
      (* Poly::Translate/Rotate/Scale all call Transform: composed into its Trans *)
      Poly { p with tr = attach (Some p.tr) op }
  | Quadric q ->
      (* Quadric::Translate/Rotate/Scale all call Transform: the coefficients change *)
      Quadric (Quadric.transform q (op_transform op))
  | Blob { blob; textures } ->
      (* Blob::Translate/Rotate/Scale all call Transform: composed into its Trans (a box already
         set up is mapped), the components' own textures moved with it *)
      Blob { blob = Blob.transform blob (op_transform op); textures = Array.map (fun t -> texture t op) textures }
  | Superellipsoid q ->
      (* Superellipsoid::Translate/Rotate/Scale all call Transform: composed into its Trans *)
      Superellipsoid (Superellipsoid.transform q (op_transform op))
  | Ovus v ->
      (* Ovus::Translate/Rotate/Scale all call Transform: composed into its Trans *)
      Ovus (Ovus.transform v (op_transform op))
  | Sphere_sweep s ->
      (* SphereSweep::Translate/Rotate/Scale move the modeling spheres until a transform is
         needed; Transform, and everything after it, composes into Trans *)
      let kind = match op with Translate v -> Sphere_sweep.Translate v | Rotate _ -> Sphere_sweep.Rotate | Scale v -> Sphere_sweep.Scale v | Transform _ -> Sphere_sweep.Other in
      Sphere_sweep (Sphere_sweep.move s kind (op_transform op))
  | Prism p ->
      (* Prism::Translate/Rotate/Scale all call Transform: composed into its Trans *)
      Prism (Prism.transform p (op_transform op))
  | Lathe l -> Lathe (Lathe.transform l (op_transform op)) (* Lathe::Transform, likewise *)
  | Sor s -> Sor (Sor.transform s (op_transform op)) (* Sor::Transform, likewise *)
  | Bicubic b ->
      (* BicubicPatch::Translate adds, Scale multiplies, Rotate and Transform map every control
         point (MTransPoint); the subdivision is rebuilt from the points at the end *)
      let mv (q : Vec.t) =
        match op with
        | Translate v -> Vec.make (q.x +. v.x) (q.y +. v.y) (q.z +. v.z)
        | Scale v -> Vec.make (q.x *. v.x) (q.y *. v.y) (q.z *. v.z)
        | Rotate _ | Transform _ -> Transform.point (op_transform op) q
      in
      Bicubic { b with points = Array.map mv b.points }
  | Isosurface i ->
      (* IsoSurface::Translate/Rotate/Scale all call Transform: composed into its Trans *)
      Isosurface (Isosurface.transform i (op_transform op))
  | Julia f ->
      (* Fractal::Translate/Rotate/Scale all call Transform: composed into its Trans, and its
         Compute_BBox clears the inverted flag *)
      Julia (Julia.transform f (op_transform op))
  | Parametric s -> Parametric (Parametric.transform s (op_transform op)) (* Parametric::Transform, for every modifier *)
  | Csg { kind; members; box } ->
      (* §16: a CSG's transform moves every member, and maps the box it has (Recompute_BBox) *)
      let members = List.map (fun (m : Scene.member) -> { m with mobj = { m.mobj with shape = shape m.mobj.shape op; texture = texture m.mobj.texture op } }) members in
      Csg { kind; members; box = csg_box box op }

(* ---------------------------------------------------------------------------------------------- *)
(* The whole scene moved: every object, light and the camera scaled by [scale] about the origin and
   then translated, with the distances that are lengths (fade distances) scaled too, so the scene
   is the same picture at another size and place (the metamorphic tests of the robust mode). *)

let scene ~scale ~translate (s : Scene.t) : Scene.t =
  let sv = Vec.make scale scale scale in
  let rec obj (o : Scene.obj) =
    (* a shape whose own Scale would change it (a smooth triangle's renormalised vertex normals)
       is scaled as a matrix, which only multiplies its vertex normals by the same factor *)
    let scaling = if (Shape_kind.of_shape o.shape).scale_by_matrix then Transform (Transform.scale sv) else Scale sv in
    let sh =
      match o.shape with
      | Csg { kind; members; box } ->
          Scene.Csg { kind; members = List.map (fun (m : Scene.member) -> { m with mobj = obj m.mobj }) members; box = csg_box (csg_box box (Scale sv)) (Translate translate) }
      | primitive -> shape (shape primitive scaling) (Translate translate)
    in
    let moved t = texture (texture t (Scale sv)) (Translate translate) in
    {
      o with
      shape = sh;
      texture = moved o.texture;
      interior_texture = Option.map moved o.interior_texture;
      interior = { o.interior with fade_distance = o.interior.fade_distance *. scale };
    }
  in
  let light (l : Scene.light) =
    let radius, falloff =
      match l.kind with Cylinder_light -> (l.radius *. scale, l.falloff *. scale) | Point_light | Spotlight -> (l.radius, l.falloff)
    in
    {
      l with
      position = Vec.add (Vec.scale scale l.position) translate;
      point_at = Vec.add (Vec.scale scale l.point_at) translate;
      fade_distance = l.fade_distance *. scale;
      radius;
      falloff;
    }
  in
  let c = s.camera in
  let camera =
    {
      Scene.location = Vec.add (Vec.scale scale c.location) translate;
      direction = Vec.scale scale c.direction;
      up = Vec.scale scale c.up;
      right = Vec.scale scale c.right;
      projection = c.projection;
    }
  in
  let far (v : Vec.t) = Float.max (Float.abs v.x) (Float.max (Float.abs v.y) (Float.abs v.z)) in
  { s with objects = List.map obj s.objects; lights = List.map light s.lights; camera; shift = (s.shift *. scale) +. far translate }
