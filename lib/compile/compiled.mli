(** The scene as the tracer uses it: built once by [Compile] from the immutable [Scene.t], holding
    only what this scene needs, in flat unboxed records. It is immutable: nothing here has a
    mutable field, and nothing is written once it is compiled but the lazy [group.pov], which is
    made on first use from the scene alone. Everything a render writes (statistics, scratch,
    caches, random streams, what it keeps for each isosurface and height field) is its worker's
    ({!Context.t}). The one exception is hidden in closures that come from the scene: a user
    function's call sites keep the frames of the functions they call ([Fn_compile]), and an object
    pattern's Inside test its traversal room ([Inside_test]), both scratch written before they are
    read; and [f_ridged_mf] keeps the octave weights of its first call ([Fn_noise]). Each worker is
    a process of its own. *)

(** Everything about a surface that does not depend on the hit point, derived once from a
    plain pigment and its finish (§3.2, §3.5, §5). A pattern pigment's surface holds the finish's
    quantities, and its [paint] gives the whole surface at each hit point (§17.1). *)
type surface = {
  colour : Rgb.t;  (** pigment rgb *)
  att : float;  (** 1 − f − t (or the legacy formula) *)
  emitted : Rgb.t;  (** ambient·ambient_light·att + emission·att, times the colour *)
  lit : bool;  (** diffuse, phong or specular is non-zero: lights are visited *)
  diffuse : float;
  brilliance : float;
  phong : float;
  phong_size : float;
  specular : float;
  spec_exp : float;  (** 1/roughness (0 when roughness is 0) *)
  metallic : float;
  refl : Scene.reflection;
  reflects : bool;  (** some reflection colour is non-zero *)
  filcol : Rgb.t;  (** rgb·filter + transmit (§3.5) *)
  transparent : bool;  (** filter or transmit non-zero: a transmitted ray may be traced *)
  conserve : bool;
  irid : float;  (** the iridescence amount (0: none), single precision *)
  irid_thickness : float;
  irid_turb : float;
  crand : float;  (** the random amount taken off each light's diffuse intensity (0: none) *)
  paint : paint;
  bump : bump;
  needs_uv : bool;
      (** the pigment or the normal is uv-mapped: the tracer gives it the hit's UV coordinates
          ({!Shape.uv}); never computed for other surfaces *)
}

(** Whether a surface's colour depends on the point. *)
and paint =
  | Fixed  (** a plain pigment: the surface is the same everywhere *)
  | Varying of (Patterns.hit -> Vec.t -> surface)
      (** a pattern pigment: the surface at a world point, its colour-dependent fields (colour, att,
          emitted, filcol, transparent) computed from the pigment there *)

(** Whether a surface's normal is bent by a normal pattern (normal.cpp). *)
and bump =
  | Smooth  (** no normal: the surface is shaded with the shape's normal *)
  | Bumpy of Scene.normal
      (** the texture's normal: at each hit it bends the shape's normal ({!Normals.perturb}), which
          then serves diffuse, highlights, the reflectivity's angle, the reflected and the
          transmitted rays *)

(** A texture as the tracer shades it (trace.cpp's ComputeOneTextureColour). *)
and texture =
  | Plain of surface  (** one layer: the common case, shaded without the layer loop *)
  | Layered of surface array
      (** two or more layers, the top first: each lit on its own and seen through the filter
          and transmit of those above it (ComputeLightedTexture) *)
  | Blended of blended  (** a patterned texture: entries picked or blended by a pattern *)
  | Chosen of { cwarp : Vec.t -> Vec.t; choose : Vec.t -> int; textures : texture array; cwarps : Scene.warp list }
      (** a material_map: at the point warped by [cwarp], [choose] picks one of [textures],
          evaluated there; [cwarps] bend their normals *)
  | Cutaway
      (** the textures of the members of the hit's top-level CSG that the point lies in, weighed
          equally (Determine_Textures); a difference's first member's *)
  | Uv_mapped of { uinner : texture; uwarps : Scene.warp list }
      (** [uinner] evaluated at the hit's (u, v, 0), its normals bent in the space of [uwarps] *)

(** A patterned texture: the pattern's value at a point picks the entries around it, each shaded
    in full at the point the pattern saw (its warps applied) and blended by the value. *)
and blended = {
  warp : Vec.t -> Vec.t;  (** the pattern's warps (Warp_EPoint) *)
  value : Patterns.hit -> Vec.t -> float;  (** the pattern's value at a warped point, wave and all *)
  values : float array;  (** the entries' values, single precision, in the order written *)
  entries : texture array;
  average : bool;  (** [average]: every entry weighed by its value, none picked *)
  nwarps : Scene.warp list;
      (** the pattern's warps, through which the normals of its entries are bent (Warp_Normal) *)
}

(** The shapes as the tracer meets them; everything about each is in its module (lib/shapes/),
    and [Shape] dispatches to it. *)
type shape =
  | Sphere of Sphere.t
  | Sphere_placed of Sphere.placed
      (** a sphere moved by modifiers baked into it, traced as [Sphere], its UV frame kept *)
  | Ellipsoid of Sphere.ellipsoid  (** §2.2, §14.5 (b): a sphere mapped by a transform *)
  | Plane of Plane.t
  | Plane_trans of Plane.moved  (** §2.3, §14.5 (a): a plane mapped by a transform *)
  | Triangle of Triangle.t
  | Smooth_triangle of Triangle.t
  | Mesh of Mesh.placed
  | Box of Box.t  (** §15.1, in world space *)
  | Box_trans of Box.moved  (** §15.1, §14.5 (a): a box mapped by a transform *)
  | Cone of Cone.t  (** §15.2, §15.3, §14.5 (b) *)
  | Disc of Disc.t  (** §15.4, §14.5 (b) *)
  | Torus of Torus.t  (** §15.5, §14.5 (b): always through its transform *)
  | Csg of csg
      (** §16: a CSG kept whole, a top-level object or a member of one. The tracer never reports a
          CSG as the object hit but the member primitive (a leaf), whose own surface is shaded. *)
  | Glyph of Glyph.t  (** §15.9: a text object's letter, always through its transform *)
  | Polygon of Polygon.t  (** §15.7, §14.5 (b): the outline in polygon space, placed by its transform *)
  | Quadric of Quadric.t  (** quadrics.cpp: in world space, the ray as it is *)
  | Blob of Blob.compiled  (** shape/blob.cpp: in blob space, through its transform if it has one *)
  | Height_field of Hfield.t
      (** hfield.cpp: the field walked in its own space, through its transform; a smooth one's
          vertex normals are the worker's *)
  | Superellipsoid of Superellipsoid.t  (** super.cpp: its own root search in its own space *)
  | Ovus of Ovus.t  (** ovus.cpp: the part hit decides the normal *)
  | Sphere_sweep of Sphere_sweep.compiled  (** sphsweep.cpp: segments and single spheres, the part hit names the normal *)
  | Prism of Prism.t  (** prism.cpp: through its transform *)
  | Lathe of Lathe.t  (** lathe.cpp: through its transform *)
  | Sor of Sor.t  (** sor.cpp: through its transform *)
  | Isosurface of Isosurface.compiled
      (** isosurf.cpp: searched in its own space, with the worker's cache, frame and max_gradient *)
  | Julia of Julia.t  (** fractal.cpp: the ray taken into fractal space, its direction renormalised *)
  | Parametric of Parametric.t  (** fpmetric.cpp: the ray taken into parametric space, not renormalised *)
  | Bicubic of Bezier.t  (** bezier.cpp: in world space, type 1 with its tree of bounding spheres *)
  | Poly of Poly.t  (** poly.cpp: poly, cubic, quartic, through its transform; unbounded *)

(** A CSG's members and how their hits are kept (§16.2, §16.3). *)
and csg = {
  kind : Scene.csg_kind;
  members : member array;  (** in the order written (§16.2) *)
  cbox : float array;  (** POV-Ray's box of the CSG, as [obj.pbox]; the ray is tested against it first *)
}

(** A CSG member's geometry: what the CSG's search, Inside test and boxes read of it. Its
    appearance is the object [t.objects.(id)]'s, whose values these are (the same shape and box,
    not copies); the tracer shades a member hit through that object. *)
and member = {
  id : int;
      (** the member's object in [t.objects]: a hit on a primitive member is reported with it
          (its leaf id) *)
  inverted : bool;  (** its Inside is negated (§16.3), as [obj.inverted] *)
  shape : shape;
  pbox : float array;  (** POV-Ray's box of the member, as [obj.pbox]: bounding objects are tested against it *)
  mag : float;  (** as [obj.mag]: a CSG's magnitude is its largest member's *)
}

(** An object's interior as the tracer uses it (POV-Ray's Interior), its values in single
    precision. Objects whose interiors are equal share one. *)
and interior = {
  ior : float;
  fade_distance : float;
  fade_power : float;
  fade_colour : Rgb.t;
  caustics : float;  (** the faked caustics (0: none), as stored *)
}

(** An object ready to trace: a top-level object, or a member of a CSG (whose geometry its
    CSG holds again as a {!member}). *)
type obj = {
  id : int;  (** its index in [t.objects]: top-level objects and their members in scene order *)
  iid : int;
      (** the identity of its interior in interior lists: its own id, or for a CSG member that
          shares its parent's interior the parent's [iid] (§16.5). [t.objects.(iid)] carries
          that interior's values. *)
  top : int;  (** the id of the top-level object it belongs to (its own id at top level) *)
  cache : int;
      (** the object the shadow cache keeps when this primitive stops a shadow ray (POV-Ray's
          Intersection.Csg, else the primitive): its outermost enclosing intersection, merge or
          clipped union, else itself; a top-level primitive whose bounding objects were removed
          and whose own box test POV-Ray keeps (not a sphere, box, plane or triangle) is kept
          with its box *)
  inverted : bool;  (** a CSG member whose Inside is negated (§16.3) *)
  shape : shape;
  tex : texture;  (** the object's own texture *)
  inner_tex : texture option;  (** its interior_texture: seen where a ray meets the surface from inside *)
  face_texs : texture array;  (** meshes: the per-face textures *)
  clear : bool;
      (** its own texture may let light through (not POV-Ray's Test_Opacity): a CSG whose texture
          is clear is not kept in the shadow cache *)
  difference : bool;  (** a CSG written as [difference] (for [Cutaway]) *)
  uv_mapped : bool;  (** [uv_mapping] on the object: its textures are evaluated at the hit's (u, v, 0) *)
  interior : interior;  (** what its interior does to light inside it *)
  old_refract : float;  (** legacy finish refraction: the transmitted-colour factor (§2.7, §6.3) *)
  opaque : bool;  (** every surface has filter = transmit = 0: stops a shadow ray at once (§2.7) *)
  mag : float;
      (** the largest coordinate magnitude the shape's intersection works with (its box, or a
          plane's point nearest the origin): the scale of its rounding errors, for the robust mode *)
  pbox : float array;
      (** POV-Ray's bounding box of the object, as it stores it: lower corner and lengths, each
          rounded to single precision; [||] for an object POV-Ray flags infinite (a plane, any
          box of volume above 2e10: {!Pov_box.infinite}), which stays out of its tree. Used to
          search objects and break exact depth ties the way POV-Ray's bounding order does (§2.1). *)
  double_illuminate : bool;  (** §16.6: lights behind the surface light it too *)
}

(** How a shadow ray is answered, chosen once for the scene (§4). *)
type shadow_mode =
  | No_occluders  (** nothing casts shadows *)
  | Any_hit  (** every occluder is opaque: the first surface met decides *)
  | Filtered  (** some occluder is transparent: walk every crossing *)

(** POV-Ray's own order of search, for the scenes whose image depends on it (see [group]). *)
type order =
  | Tree of {
      tree : Slab_tree.t;  (** POV-Ray's bounding tree over every top-level object *)
      member : bool array;  (** by object id: whether the group holds the object *)
    }  (** with its bounding tree: nearest box first *)
  | Listed of obj array  (** without it: the group's objects, every one, in scene order *)

(** Objects as the tracer searches them: unbounded ones (planes, infinite quadrics, …) one by one, the others through a
    bounding-volume hierarchy whose leaves index [bounded]. *)
type group = {
  unbounded : obj array;
  bounded : obj array;  (** in the hierarchy's leaf order *)
  bvh : Bvh.t;
  spheres : float array;
      (** 4 per bounded object: a sphere's centre and radius², tested without touching the object
          record; radius² is nan for other shapes *)
  boxes : float array;
      (** 6 per bounded object: the box of a shape costlier to test than a box
          ([Shape.costly]), as its hierarchy leaf would hold it alone (min x, y,
          z, max x, y, z), met by a ray before the shape itself is tried; nan for other shapes *)
  pov : order Lazy.t;
      (** the group searched as POV-Ray searches it (through its bounding tree, or in scene order
          without it): replayed for a ray on which two top-level objects' hits nearly tie (equal
          but for rounding), where which one POV-Ray finds depends on its order of search. Made
          when a ray first needs it, a function of the group's objects alone (so that a scene of a
          million objects builds POV-Ray's tree only if some ray asks for it); its walk's room is
          the worker's ({!Context.t.pov_room}) *)
  pov_always : bool;
      (** every ray searches [pov]: scenes with isosurfaces, whose shared cache of the last
          segment without a root (isosurf.cpp) answers according to which isosurface was searched
          last, and scenes whose coordinates are large against an object, which POV-Ray's
          single-precision boxes miss in part *)
}

type t = {
  objects : obj array;
      (** every object, in scene order, each CSG followed by its members (depth first); [id]
          indexes this array. The groups hold the top-level objects only. *)
  all : group;  (** every object *)
  seen : group;  (** what image rays can hit: the objects without no_image ([all] when none has it) *)
  mirrored : group;
      (** what reflection rays can hit: the objects without no_reflection ([all] when none has it) *)
  occluders : group;  (** objects without no_shadow *)
  shadow_mode : shadow_mode;
  lights : Light.t array;
  background : Colour.t;
  sky : Scene.sky option;
  max_trace_level : int;
  adc_bailout : float;
  noise_generator : int;  (** the scene's, for patterns that name none *)
  irid_wavelength : Rgb.t;  (** the wavelengths of iridescence *)
  uses_crand : bool;
      (** some surface has a crand: its random stream ({!Context.t.crand}) runs through the blocks
          in render order, so the render runs in one worker, whose order is POV-Ray's one-thread
          order *)
  legacy : bool;  (** effective version < 3.70 *)
  camera : Scene.camera;
  start_interiors : int list;
      (** interiors containing the camera, last entered first (§6.4): a perspective camera's rays
          start in them ({!Camera}) *)
  shift : float;
      (** the scene's {!Scene.t.shift}: the rounding of a move of the whole scene leaves surfaces
          that were coplanar apart by a few units in the last place of it *)
  robust_start_interiors : int list;  (** the same in the robust mode's order ({!Interiors.innermost_first}) *)
  screen_holders : obj array;
      (** orthographic camera: the top-level objects whose box can hold a ray's origin, in scene
          order (§18.4); empty otherwise *)
  bounding : bool;
      (** POV-Ray builds its bounding hierarchy: bounding is on and the scene has at least
          Bounding_Threshold top-level objects (1 by default, 3 in Debian's povray.ini), light
          sources and degenerate triangles included. Without it objects are tested in scene order,
          which decides exact depth ties. *)
}
