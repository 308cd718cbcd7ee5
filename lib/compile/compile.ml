(* The compile step (docs/povray-rules.md §2.7, §3, §16.5): the immutable scene turned once into what the
   tracer reads: objects numbered with their interiors, shapes through [Shape.compile], surfaces
   with their constant parts folded, lights, the groups each kind of ray searches, the shadow
   strategy and the camera's starting interiors. *)

open Compiled

let f32 = Precision.f32

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

(* A group of top-level objects: povml's hierarchy over them, and [pov], how POV-Ray's search
   meets them (see {!Compiled.group}) *)
let group ~pov ~pov_always objs =
  let pov = pov objs in
  let unbounded = List.filter (fun o -> Shape.bounds o.shape = None) objs in
  let bounded = List.filter (fun o -> Shape.bounds o.shape <> None) objs in
  let boxes = Bvh.create_boxes (List.length bounded) in
  List.iteri (fun i o -> let b = Option.get (Shape.bounds o.shape) in Bvh.set_box boxes i b.(0) b.(1) b.(2) b.(3) b.(4) b.(5)) bounded;
  let bvh, perm = Bvh.renumber (Bvh.build boxes) in
  let objs = Array.of_list bounded in
  let bounded = Array.map (fun i -> objs.(i)) perm in
  (* each costly shape's own box, stored as the hierarchy stores a leaf's (widened, single
     precision), in leaf order *)
  let own = Bvh.create_boxes (Array.length bounded) in
  Array.iteri (fun i o -> let b = Option.get (Shape.bounds o.shape) in Bvh.set_box own i b.(0) b.(1) b.(2) b.(3) b.(4) b.(5)) bounded;
  let boxes = Array.make (6 * Array.length bounded) nan in
  Array.iteri
    (fun i o -> if Shape.costly o.shape then for k = 0 to 5 do boxes.((6 * i) + k) <- Bigarray.Array1.get own ((6 * i) + k) done)
    bounded;
  let spheres = Array.make (4 * Array.length bounded) nan in
  Array.iteri
    (fun i o ->
      match Shape.as_sphere o.shape with
      | Some (s : Sphere.t) -> spheres.(4 * i) <- s.cx; spheres.((4 * i) + 1) <- s.cy; spheres.((4 * i) + 2) <- s.cz; spheres.((4 * i) + 3) <- s.r2
      | None -> ())
    bounded;
  { unbounded = Array.of_list unbounded; bounded; bvh; spheres; boxes; pov; pov_always }

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
    if legacy then 1. -. ((c.filter *. Rgb.max3 colour) +. c.transmit)
    else (* the colour's opacity, a single-precision value in POV-Ray *) f32 (1. -. c.filter -. c.transmit)
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
    filcol =
      (* black, one value for every opaque colour (f32 (f32 (x *. 0.) +. 0.) is 0) *)
      (if c.filter = 0. && c.transmit = 0. then Rgb.black
       else Rgb.make (f32 (f32 (c.red *. c.filter) +. c.transmit)) (f32 (f32 (c.green *. c.filter) +. c.transmit)) (f32 (f32 (c.blue *. c.filter) +. c.transmit)));
    transparent = c.filter <> 0. || c.transmit <> 0.;
  }

(* What a surface takes from its layer's finish and normal (the finish in single precision, and
   the surface without its colour), given whether its pigment or normal reads UV coordinates. *)
let finished ((f0 : Scene.finish), (normal : Scene.normal option), needs_uv) =
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
      irid = f32 f.irid;
      irid_thickness = f32 f.irid_thickness;
      irid_turb = f32 f.irid_turb;
      crand = f32 f.crand;
      paint = Fixed;
      (* the normal, if any, is perturbed at each hit; without one the tracer never looks *)
      bump = (match normal with None -> Smooth | Some nm -> Bumpy nm);
      needs_uv;
    }
  in
  (f, base)

let surface_with ~finished ~legacy ~noise ~ambient_light (t : Scene.layer) =
  (* UV coordinates are computed only for a surface that reads them *)
  let needs_uv = Pigment.uses_uv t.pigment || (match t.normal with None -> false | Some nm -> Pigment.normal_uses_uv nm) in
  let f, base = finished (t.finish, t.normal, needs_uv) in
  let ambient_light = rgb32 ambient_light in
  match t.pigment with
  | Solid c | Solid_placed { colour = c; _ } -> coloured ~legacy ~ambient_light f base (colour32 c)
  | Pattern p ->
      (* §17.1: the map colours are single precision already, and so is their blend *)
      let at hit x = coloured ~legacy ~ambient_light f base (Pigment.eval noise p hit x) in
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

(* Test_Opacity: a texture stops light when one of its layers is opaque; a patterned texture is
   never taken as opaque *)
let rec texture_opaque (t : Scene.texture) =
  match t with
  | Layers ls -> List.exists (fun (l : Scene.layer) -> pigment_opaque l.pigment) ls
  | Material_map { mimage; materials; _ } -> (not mimage.once) && Array.for_all texture_opaque materials
  | Texture_pattern _ | Uv_mapped _ | Cutaway -> false

(* the top layer's finish, which holds the legacy refraction and ior (§2.7) *)
let top_finish (t : Scene.texture) = match t with Layers (l :: _) -> Some l.finish | Layers [] | Texture_pattern _ | Uv_mapped _ | Material_map _ | Cutaway -> None

(* Objects whose layers are the same share one compiled surface: a declared texture, and the
   layers written out alike for every object of an export (a million spheres each with its own
   [pigment { rgb 1 }]), which would otherwise cost a compiled surface each; and surfaces whose
   finish and normal are the same share the parts that come from them. What is compiled is a pure
   function of what it is compiled from, so equal inputs give equal results. Inputs are the same
   when physically equal or equal in structure; one holding a function closure is equal only to
   itself. Each hash keeps the few inputs met last, so a lookup costs a bounded number of
   comparisons however many objects there are; an input that has dropped out is compiled again. *)
module Same_memo : sig
  type ('k, 'v) t

  val create : unit -> ('k, 'v) t
  (** [create ()] is an empty memo. *)

  val find_or_add : ('k, 'v) t -> 'k -> ('k -> 'v) -> 'v
  (** [find_or_add memo k make] is the value kept for an input the same as [k], or [make k], kept. *)
end = struct
  type ('k, 'v) t = (int, ('k * 'v) list) Hashtbl.t

  let kept = 8
  let create () = Hashtbl.create 64
  let same a b = a == b || match compare a b with 0 -> true | _ -> false | exception Invalid_argument _ -> false

  let find_or_add memo k make =
    let h = Hashtbl.hash k in
    let bucket = Option.value (Hashtbl.find_opt memo h) ~default:[] in
    match List.find_opt (fun (k', _) -> same k' k) bucket with
    | Some (_, v) -> v
    | None ->
        let v = make k in
        Hashtbl.replace memo h ((k, v) :: List.filteri (fun i _ -> i < kept - 1) bucket);
        v
end

(* A patterned texture's pattern, its value taken as a pigment's is (§17.1) *)
let blended ~noise (tpat : Scene.patterned) values entries : blended =
  let g = if tpat.noise_generator = 0 then noise else tpat.noise_generator in
  let { Scene.pattern; frequency; phase; wave; warps; _ } = tpat in
  {
    warp = (fun q -> Warp.point warps pattern q);
    value = (fun hit q -> Pigment.shape_value ~frequency ~phase wave (Patterns.value_with ~frequency ~phase pattern warps g hit q));
    values;
    entries;
    average = (match pattern with Average -> true | _ -> false);
    nwarps = warps;
  }

(* a member's geometry is its object's: the same shape and box *)
let member (ob : obj) : member = { id = ob.id; inverted = ob.inverted; shape = ob.shape; pbox = ob.pbox; mag = ob.mag }

(* POV-Ray's Bounding_Threshold when no ini file sets it (scene.cpp) *)
let pov_bounding_threshold = 1

(* What the tracer's groups ask of a top-level object once the scene's object is let go *)
type seen = { no_shadow : bool; no_image : bool; no_reflection : bool }

let scene ?(bounding_threshold = pov_bounding_threshold) (s : Scene.t) : Compiled.t =
  let scene_objects = s.objects in
  let s = { s with objects = [] } in
  (* POV-Ray builds its tree when the scene has at least Bounding_Threshold objects, light sources
     counted (boundingtask.cpp); a light's looks_like shape belongs to the light's top-level
     object (§19.2) *)
  let count = List.fold_left (fun n (o : Scene.obj) -> if o.looks_like then n else n + 1) 0 scene_objects + List.length s.lights in
  let legacy = s.version < 370 in
  let memo = Same_memo.create () and bases = Same_memo.create () in
  let noise = s.noise_generator in
  let uses_crand = ref false in
  let surface_of (l : Scene.layer) =
    Same_memo.find_or_add memo l (fun l ->
        if l.finish.crand > 0. then uses_crand := true;
        surface_with ~legacy ~noise ~ambient_light:s.ambient_light ~finished:(fun k -> Same_memo.find_or_add bases k finished) l)
  in
  let interiors = Same_memo.create () in
  let interior_of (i : Scene.interior) =
    Same_memo.find_or_add interiors i (fun i ->
        { ior = f32 i.ior; fade_distance = f32 i.fade_distance; fade_power = f32 i.fade_power; fade_colour = rgb32 i.fade_colour; caustics = i.caustics })
  in
  let rec texture_of (t : Scene.texture) : texture =
    match t with
    | Layers [ l ] -> Plain (surface_of l)
    | Layers ls -> Layered (Array.of_list (List.map surface_of ls))
    | Texture_pattern { tpat; tmap } ->
        Blended
          (blended ~noise tpat (Array.map (fun (e : Scene.texture_entry) -> f32 e.tvalue) tmap)
             (Array.map (fun (e : Scene.texture_entry) -> texture_of e.ttexture) tmap))
    | Uv_mapped { uwarps; inner } -> Uv_mapped { uinner = texture_of inner; uwarps }
    | Cutaway -> Cutaway
    | Material_map { mimage; mwarps; materials } ->
        let count = Array.length materials in
        Chosen
          {
            cwarp = (fun q -> Warp.point mwarps (Bitmap mimage) q);
            choose = (fun q -> Image_map.material mimage q count);
            textures = Array.map texture_of materials;
            cwarps = mwarps;
          }
  in
  (* Objects are numbered in scene order, each CSG before its members (the numbering keeps the
     scene order of top-level objects, which decides ties without a bounding hierarchy). *)
  let next = ref 0 and built = ref [] in
  (* isosurfaces are numbered apart, for the state a worker keeps for each *)
  let iso_slots = ref 0 in
  let rec build ?(cache = -1) ?(wrapper = -1) ~top ~iid ~inverted (o : Scene.obj) : obj option =
    let id = !next in
    (* POV-Ray's object of this node: its clipped_by and bounded_by wrappers are the node *)
    let pov_object = if wrapper >= 0 then wrapper else id in
    let top = if top < 0 then id else top and iid = if iid < 0 then id else iid in
    let rec union_core (o : Scene.obj) =
      match o.shape with
      | Csg { kind = Union; _ } -> true
      | Csg { kind = Bounded | Boxed; members = m :: _ } -> union_core m.mobj
      | _ -> false
    in
    (* a CSG is opaque when every member is *)
    let members_opaque = ref true in
    let shape =
      match o.shape with
      | Csg { kind; members; box } ->
          incr next;
          let sets_csg =
            match (kind, members) with
            | (Intersection | Merge), _ -> true
            | Clipped, m :: _ -> union_core m.mobj
            | (Union | Clipped | Bounded | Boxed), _ -> false
          in
          let cache = if cache < 0 && sets_csg then pov_object else cache in
          let members =
            List.mapi
              (fun k (m : Scene.member) ->
                let wrapper = match kind with (Clipped | Bounded | Boxed) when k = 0 -> pov_object | _ -> -1 in
                build ~cache ~wrapper ~top ~iid:(if m.own_interior then -1 else iid) ~inverted:m.inverted m.mobj)
              members
            |> List.filter_map Fun.id
          in
          members_opaque := List.for_all (fun (m : obj) -> m.opaque) members;
          let members = Array.of_list (List.map member members) in
          (* the box its history gave it, else one made from its members *)
          let cbox = match box with Some b -> b | None -> Shape.pov_box (Csg { kind; members; cbox = [||] }) in
          Some (Csg { kind; members; cbox })
      | _ ->
          (* a primitive: [Shape.compile] knows every one *)
          let sh = Shape.compile ~iso_slot:!iso_slots o.shape in
          if sh <> None then incr next;
          (match sh with Some (Isosurface _) -> incr iso_slots | Some _ | None -> ());
          sh
    in
    match shape with
    | None -> None
    | Some shape ->
        (* a blob whose components carry textures is textured by their blend (Cutaway's path,
           Surfaces.cutaway): its own texture comes last among the components' *)
        let blended = match shape with Blob b -> b.textured | _ -> false in
        let tex = if blended then Compiled.Cutaway else texture_of o.texture in
        (* a mesh's faces may carry textures of their own; no other shape has any *)
        let face_textures =
          match o.shape with Mesh m -> m.textures | Blob b when blended -> Array.append b.textures [| o.texture |] | _ -> [||]
        in
        let face_texs = Array.map texture_of face_textures in
        let opaque =
          match shape with
          | Csg _ -> !members_opaque
          | _ ->
              (* §17.8: opaque only if no colour the pigments can give is transparent *)
              texture_opaque o.texture
              && Option.fold ~none:true ~some:texture_opaque o.interior_texture
              && Array.for_all texture_opaque face_textures
        in
        let clear = match tex with Plain sf -> sf.transparent | Layered _ | Blended _ | Uv_mapped _ | Chosen _ | Cutaway -> not (texture_opaque o.texture) in
        let ob =
          {
            id;
            iid;
            top;
            cache = (if cache >= 0 then cache else pov_object);
            inverted;
            shape;
            tex;
            inner_tex = (if blended then None (* Determine_Textures has no interior texture *) else Option.map texture_of o.interior_texture);
            face_texs;
            clear;
            uv_mapped = o.uv_mapped;
            difference = o.difference;
            interior = interior_of o.interior;
            (* 1 (the common case) is one shared constant, not a float boxed per object *)
            old_refract = (match top_finish o.texture with Some f when f.refraction <> 1. -> f32 f.refraction | Some _ | None -> 1.);
            opaque;
            (* a move of the whole scene is baked into these shapes, but composed into the
               others' transforms, whose forward and inverse then disagree by the rounding of
               the move's coordinates *)
            mag =
              (Shape.magnitude shape
              +. match shape with Sphere _ | Plane _ | Triangle _ | Smooth_triangle _ | Box _ -> 0. | _ -> s.shift);
            (* an object POV-Ray flags infinite has no box in its tree *)
            pbox = (let b = Shape.pov_box shape in if Pov_box.infinite b then [||] else b);
            double_illuminate = o.double_illuminate;
          }
        in
        built := ob :: !built;
        Some ob
  in
  (* the members of a split union that share its interior name the first one's (§16.5) *)
  let shared = Hashtbl.create 8 in
  let top_level (o : Scene.obj) =
    let iid = if o.shared_interior < 0 then -1 else Option.value (Hashtbl.find_opt shared o.shared_interior) ~default:(-1) in
    let ob = build ~top:(-1) ~iid ~inverted:false o in
    (match ob with Some ob when o.shared_interior >= 0 && iid < 0 -> Hashtbl.replace shared o.shared_interior ob.id | Some _ | None -> ());
    Option.map (fun ob -> ({ no_shadow = o.no_shadow; no_image = o.no_image; no_reflection = o.no_reflection }, ob)) ob
  in
  (* the scene's objects are compiled as the last thing that reads them, so that each one is let
     go once compiled: a scene of a million objects is not held twice *)
  let visible = List.filter_map top_level scene_objects in
  let objects = Array.of_list (List.sort (fun a b -> compare a.id b.id) !built) in
  let tops = List.map snd visible in
  let casts = List.filter_map (fun (o, ob) -> if o.no_shadow then None else Some ob) visible in
  let occluders = casts in
  let shadow_mode =
    if occluders = [] then No_occluders
    else if List.for_all (fun o -> o.opaque) occluders then Any_hit
    else Filtered
  in
  let stack = Array.make 512 0. in
  let lights = Array.of_list (List.map Light.compile s.lights) in
  let cam = s.camera.location in
  let bounding = count > 0 && count >= bounding_threshold in
  let finite, infinite = List.partition (fun o -> Array.length o.pbox > 0) tops in
  let slabs = lazy (Slab_tree.build (List.map (fun o -> (o.id, o.pbox)) finite) (List.map (fun o -> o.id) infinite)) in
  (* Isosurfaces share one cache, the last segment on which one found no root: which isosurface
     was searched last, and how often, decides what it answers, so a scene with isosurfaces is
     searched in POV-Ray's order (a replay would search one twice) *)
  let isosurfaces = Array.exists (fun o -> match o.shape with Isosurface _ -> true | _ -> false) objects in
  (* POV-Ray meets an object only if the ray, its origin in single precision, crosses the
     object's single-precision box. Where coordinates are large against an object (a ball of 1e-3
     a million units from the origin) that rounding is much larger than the object, and POV-Ray
     misses parts of it or all of it: such a scene is searched as POV-Ray searches it. *)
  let coarse =
    let big (v : Vec.t) = Float.max (Float.abs v.x) (Float.max (Float.abs v.y) (Float.abs v.z)) in
    let reach (b : float array) = Array.fold_left (fun m k -> Float.max m (Float.abs b.(k) +. b.(k + 3))) 0. [| 0; 1; 2 |] in
    let extent = List.fold_left (fun m (l : Scene.light) -> Float.max m (big l.position)) (big cam) s.lights in
    let extent = List.fold_left (fun m o -> Float.max m (reach o.pbox)) extent finite in
    (* a unit in the last place of single precision at that extent, against each object's size *)
    let ulp = extent *. 0x1p-24 in
    List.exists (fun o -> ulp > 1e-3 *. Float.max o.pbox.(3) (Float.max o.pbox.(4) o.pbox.(5))) finite
  in
  (* POV-Ray's search of a group's objects: its tree, or scene order without one *)
  let pov members =
    lazy
      (if bounding then begin
         let member = Array.make (Array.length objects) false in
         List.iter (fun o -> member.(o.id) <- true) members;
         Tree { tree = Lazy.force slabs; member }
       end
       else
         let listed = Array.of_list members in
         Array.sort (fun (a : obj) b -> Int.compare a.id b.id) listed;
         Listed listed)
  in
  let group = group ~pov ~pov_always:(isosurfaces || coarse) in
  let all = group tops in
  (* §16.6: image rays never meet no_image objects, reflection rays never meet no_reflection ones
     (tested on top-level objects, §16.4); a scene without those flags searches one group for every
     ray *)
  let without keep =
    if List.for_all (fun (o, _) -> keep o) visible then all
    else group (List.filter_map (fun (o, ob) -> if keep o then Some ob else None) visible)
  in
  (* §6.4: the camera ray starts inside every object that contains the camera location; the list
     is kept with the last entered first, and holds interiors: a CSG's members share theirs (§16.5) *)
  let holds o = Interiors.holds stack o cam in
  let holders = List.filter holds tops in
  let start_interiors =
    match holders with
    | [] | [ _ ] -> List.map (fun o -> o.iid) holders
    | _ :: _ :: _ ->
        (* with its bounding tree POV-Ray meets the objects in the tree's order, else in scene
           order; the order matters only when the camera is inside two or more, and only then is
           the tree built *)
        let candidates =
          if bounding then Slab_tree.walk (Lazy.force slabs) (fun b -> Pov_box.contains b cam)
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
    shift = s.shift;
    robust_start_interiors = Interiors.innermost_first objects start_interiors;
    (* POV-Ray keeps the background colour in single precision *)
    background = colour32 s.background;
    sky = s.sky;
    max_trace_level = s.max_trace_level;
    adc_bailout = s.adc_bailout;
    noise_generator = s.noise_generator;
    irid_wavelength = s.irid_wavelength;
    legacy;
    camera = s.camera;
    start_interiors;
    screen_holders = screen_holders s.camera tops;
    bounding;
    uses_crand = !uses_crand;
  }
