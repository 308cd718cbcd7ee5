(** The immutable scene: what the interpreter produces and the compile step reads.
    Every value reachable from [t] is immutable. *)

(** How an image's pixels are read (ImageData's Use): an image_map's or bump_map's [use_index]
    is [Use_none], which takes the palette index where there is one. *)
type image_use =
  | Use_none  (** the palette index, where the image has a palette *)
  | Use_colour  (** the colour (the default of all three) *)
  | Use_index  (** image_pattern's [use_index]: stored, but POV-Ray still takes the grey *)
  | Use_alpha  (** image_pattern's [use_alpha]: the transmit (1 − alpha), or red without alpha *)

(** An image mapped onto pattern space, as image_map, bump_map and image_pattern hold it
    (POV-Ray's ImageData, backend/support/imageutil.cpp). *)
type bitmap = {
  image : Image_file.t;  (** the decoded pixels, with the palette's per-index filter and transmit *)
  file : string;  (** the file name as written, for [--dump] *)
  map_type : int;  (** 0 planar, 1 spherical, 2 cylindrical, 5 torus; any other is planar *)
  interpolate : int;  (** 0 none, 2 bilinear, 3 bicubic, 4 normalised distance; others as bilinear *)
  once : bool;  (** no repetition: points off the image have no colour *)
  use : image_use;
  width : float;  (** the image's width times the repeat, single precision *)
  height : float;
  offset_u : float;  (** the offset times minus the image's width *)
  offset_v : float;
  all_filter : float;  (** [filter all]: added to every pixel's filter (non-palette images) *)
  all_transmit : float;
  has_filter : bool;  (** [filter] or [transmit] was written (POV-Ray's HAS_FILTER) *)
  bump_size : float option;  (** bump_map's [bump_size], which the normal's amount takes *)
}

(** A pattern: a function from a point in pattern space to a value (docs/povray-rules.md §17.4–§17.7;
    the others as POV-Ray 3.7's pattern.cpp defines them). Values stored in single precision by
    POV-Ray ([SNGL]) are rounded when parsed. *)
type pattern =
  | Checker  (** §17.4: 0 or 1 by the parity of the unit cell *)
  | Gradient of Vec.t  (** §17.5: the direction, normalised when parsed *)
  | Hexagon  (** §17.6: 0, 1 or 2 in the XZ plane *)
  | Brick of { size : Vec.t; mortar : float }  (** §17.7: 0 in the mortar, 1 in a brick; [mortar] as stored (m − 2e-10) *)
  | Square  (** 0…3: four cells of a square tiling of the XZ plane *)
  | Triangular  (** 0…5: six cells of a triangular tiling of the XZ plane *)
  | Cubic  (** 0…5: the six pyramids of the unit cube around the origin *)
  | Agate of float  (** agate, with [agate_turb] (single precision, 1 by default) *)
  | Bozo  (** the solid noise *)
  | Spotted  (** the solid noise (as bozo) *)
  | Bumps  (** the solid noise as a pigment; its own normal *)
  | Granite
  | Leopard
  | Marble  (** uses the classic turbulence itself; triangle_wave by default *)
  | Wood  (** uses the classic turbulence itself; triangle_wave by default *)
  | Onion
  | Radial
  | Cells
  | Crackle of { form : Vec.t; metric : float; offset : float; solid : bool }
      (** defaults: form <-1,1,0>, metric 2, offset 0, not solid *)
  | Wrinkles
  | Dents
  | Waves of int  (** with the number_of_waves of global_settings read before it (10 by default) *)
  | Ripples of int
  | Quilted of { control0 : float; control1 : float }  (** single precision, 1 and 1 by default *)
  | Facets of { fsize : float; coords : float; fmetric : float }
      (** normal only: size 0.1, metric 2; [coords] as written (0: off), which also scales the bend *)
  | Spiral1 of int  (** the number of arms *)
  | Spiral2 of int
  | Planar
  | Boxed
  | Spherical
  | Cylindrical
  | Fractal of fractal  (** mandel, julia, magnet *)
  | Pavement of { side : int; tile : int; number : int; exterior : int; interior : int; form : int }
      (** defaults: side 3, tile 1, number 1, exterior 0, interior 0, form 0 *)
  | Tiling of int  (** the tiling's number, 1…27 *)
  | Aoi  (** the angle between the ray and the surface normal *)
  | Slope of slope
  | Average  (** a normal's [average] of the entries of its normal_map *)
  | No_pattern
      (** a normal written without a pattern: allowed only as [#default]'s, the base that later
          normals edit; an object left with it is refused (POV-Ray: "No normal type given") *)
  | Pigment_pattern of pigment_probe
      (** pattern.cpp pigment_pattern: the greyscale (single precision) of a pigment's colour at
          the point *)
  | Object_pattern of object_test
      (** pattern.cpp object_pattern: 1 where the point is inside the object, 0 outside; a block
          pattern with two entries (checker's default map), frequency 0 *)
  | Bitmap of bitmap
      (** POV-Ray's BITMAP_PATTERN: an image_map in a pigment (whose colour is the image's,
          its map unused) or a bump_map in a normal (the image's slope); it has no value *)
  | Image_pattern of bitmap  (** image_pattern: the image's grey, index or alpha as the value *)
  | Function_pattern of Fn.t
      (** pattern.cpp function_pattern: the function of x y z at the point, reduced modulo 1
          when above 1 *)

(** The pigment of a [pigment_pattern], reduced to what the pattern needs (as an object
    pattern's object, for the same reason): the grey of its colour at a pattern-space point (0
    where it gives none), and its [--dump] text, both made once when it was parsed. *)
and pigment_probe = { grey : Vec.t -> float; pshown : string }

(** The object of an [object] pattern, reduced to what the pattern needs: [pattern] comes before
    [obj] in this file (and one recursive group would clash labels), so the object itself is kept
    as its Inside test and its [--dump] text, both made once when it was parsed. The object is the
    one parsed, moved by the transforms written inside the pattern's block, never by the
    pattern's own (those move the point instead). *)
and object_test = {
  inside : Vec.t -> bool;
      (** POV-Ray's Inside_Object of the object at a pattern-space point; it owns its traversal
          room, so it must not be called from two threads at once (povml's workers are
          processes, lib/render/pool.mli) *)
  shown : string;  (** the object as [--dump] prints it *)
}

(** mandel, julia and magnet patterns (pattern.cpp's fractal fields). *)
and fractal = {
  fkind : fractal_kind;
  iterations : int;
  exponent : int;  (** 2 by default for mandel and julia; 0 for magnet *)
  interior_type : int;  (** 0 by default *)
  exterior_type : int;  (** 1 by default *)
  ifactor : float;  (** 1 by default *)
  efactor : float;  (** 1 by default *)
}

and fractal_kind =
  | Mandel
  | Julia of float * float  (** the complex parameter *)
  | Magnet_mandel of int  (** magnet 1 or 2 mandel *)
  | Magnet_julia of int * (float * float)  (** magnet 1 or 2 julia, with its parameter *)

(** The slope pattern's fields as POV-Ray stores them after parsing. *)
and slope = {
  slope_vector : Vec.t;  (** normalised unless of zero length *)
  altit_vector : Vec.t;
  slope_base : int;  (** ±(axis + 1) when [slope_vector] is ±x, ±y or ±z, else 0 *)
  altit_base : int;
  slope_len : float;  (** the slope's share, slope_len + altit_len = 1 *)
  altit_len : float;
  slope_mod : float * float;  (** low and (high − low), or 0, 0 *)
  altit_mod : float * float;
  point_at : bool;
}

(** How the wrapped pattern value is shaped before the map lookup (§17.1). *)
type wave = Ramp | Triangle_wave | Sine_wave | Scallop_wave | Cubic_wave | Poly_wave of float

(** Turbulence: the amount per axis, octaves (1…10, 6 by default), omega (0.5) and lambda (2),
    the last two in single precision. *)
type turb = Noise.turb = { turbulence : Vec.t; octaves : int; omega : float; lambda : float }

(** A warp of pattern space (warps.cpp). A pattern's warps are a list whose head is the last one
    written: the point is taken through them from the head (undoing the last transform first). *)
type warp =
  | Transform_warp of Transform.t  (** consecutive transforms compose into one *)
  | Classic_turb of turb
      (** the [turbulence] keyword written directly in a pattern: always the list's last element;
          marble and wood skip it here and use it themselves *)
  | Turb_warp of turb  (** [warp { turbulence … }] *)
  | Repeat_warp of { axis : int; width : float; offset : Vec.t; flip : Vec.t }
      (** [width] single precision; [flip] components are −1 (flipped) or 1 *)
  | Black_hole of {
      centre : Vec.t;
      radius : float;
      strength : float;
      power : float;  (** [falloff], 2 by default *)
      inverted : bool;
      bh_type : int;
      repeat : Vec.t option;
      uncertainty : Vec.t option;  (** [turbulence] in a black hole *)
    }
  | Cylindrical_warp of { orientation : Vec.t; dist_exp : float }  (** orientation <0,0,1> by default *)
  | Spherical_warp of { orientation : Vec.t; dist_exp : float }
  | Toroidal_warp of { orientation : Vec.t; dist_exp : float; major_radius : float }  (** major radius 1 *)
  | Planar_warp of { orientation : Vec.t; offset : float }
  | Cubic_warp

(** One entry of a colour map: its value (single precision, §17.2) and colour. *)
type map_entry = { value : float; colour : Colour.t }

(** A pattern pigment: the pattern, its modifiers, its map (entries in the order written, at least
    one) and its transform (pigment and object transforms composed, §14.7, §17.1). *)
type patterned = {
  pattern : pattern;
  frequency : float;
  phase : float;
  wave : wave;
  map : map_entry array;
  warps : warp list;  (** transforms and warps, the last written first *)
  noise_generator : int;  (** 1, 2 or 3; 0: the scene's ([global_settings], 2 by default) *)
  pigments : pigment_entry array;
      (** a [pigment_map] or [checker pigment {…}, pigment {…}] (§17.3): when not empty, these
          entries are looked up instead of [map], their pigments evaluated at the same
          pattern-space point and blended *)
  uv_mapping : bool;
      (** [pigment { uv_mapping … }] (POV-Ray's UV_MAP_PATTERN around the pigment read after the
          keyword): the pattern is evaluated at the hit's (u, v, 0) taken through [warps] (the
          transforms written after the keyword), and transforms applied to the pigment later (the
          object's, the texture's) are dropped, as POV-Ray puts them on the wrapper it never
          warps *)
}

(** One entry of a pigment map: its value (single precision) and pigment. *)
and pigment_entry = { pvalue : float; pigment : pigment }

(** A pigment: a plain colour, or a pattern evaluated at each point (§17). *)
and pigment =
  | Solid of Colour.t
  | Pattern of patterned
  | Solid_placed of { colour : Colour.t; strans : Transform.t }
      (** a plain colour that was transformed: the same everywhere, but a later edit that gives
          it a pattern keeps the transform (§17.9) *)

(** [reflection {…}] of a finish (docs/povray-rules.md §5.1). *)
type reflection = {
  rmin : Rgb.t;  (** reflection at normal incidence (or the only value) *)
  rmax : Rgb.t;  (** reflection at grazing incidence *)
  fresnel : bool;  (** type 1: Fresnel blend of min and max (§5.2) *)
  falloff : float;  (** exponent of the (1 − cos) blend *)
  exponent : float;  (** reflection exponent E as written; 1 means none *)
  refl_metallic : float;  (** metallic reflection amount *)
}

(** A finish (§3, §5, §10.1). Values are as written, after albedo conversion. *)
type finish = {
  ambient : Rgb.t;
  emission : Rgb.t;
  diffuse : float;
  brilliance : float;
  phong : float;
  phong_size : float;
  specular : float;
  roughness : float;  (** as written; the specular exponent is 1/roughness *)
  metallic : float;
  reflection : reflection;
  conserve_energy : bool;
  refraction : float;  (** legacy [refraction]: the transmitted-colour factor, 1 by default (§2.7) *)
  legacy_ior : float option;  (** legacy [finish { ior }], copied into the interior (§2.7) *)
  legacy_caustics : float option;  (** legacy [finish { caustics }], copied into the interior as written *)
  irid : float;  (** [irid { amount … }]: the thin-film interference's amount, 0 without *)
  irid_thickness : float;  (** the film's thickness *)
  irid_turb : float;  (** the film thickness's turbulence (the x of the vector written) *)
  crand : float;  (** [crand]: a random amount taken off each light's diffuse intensity, 0 without *)
}

(** A normal: a pattern perturbing the surface normal (normal.cpp). *)
type normal = {
  npattern : pattern;
  nfrequency : float;
  nphase : float;
  nwave : wave;
  nwarps : warp list;  (** as a pigment's *)
  nnoise_generator : int;
  amount : float;  (** the bump size, single precision *)
  accuracy : float;  (** the finite-difference step, 0.02 by default, single precision *)
  no_bump_scale : bool;
  nmap : normal_map;
  nuv_mapping : bool;
      (** [normal { uv_mapping … }]: as a pigment's [uv_mapping], the normal is perturbed at the
          hit's (u, v, 0), and the result normalised (Perturb_Normal's UV_MAP_PATTERN case) *)
}

(** What a normal's pattern value is turned into. *)
and normal_map =
  | No_map  (** the pattern's own normal, or its value's slope *)
  | Slope_map of slope_entry array
  | Normal_map of normal_entry array

(** One entry of a slope_map: its value, height and slope (single precision). *)
and slope_entry = { svalue : float; height : float; slope : float }

(** One entry of a normal_map: its value and normal. *)
and normal_entry = { nvalue : float; nnormal : normal }

(** A plain texture, one layer of a texture: a pigment, an optional normal and a finish. *)
type layer = { pigment : pigment; normal : normal option; finish : finish }

(** A texture (trace.cpp's TEXTURE): plain layers, or a pattern choosing or blending whole
    textures. *)
type texture =
  | Layers of layer list
      (** a plain or layered texture: the top layer (the last written) first, never empty. Each
          layer is lit on its own and seen through the filter and transmit of those above it *)
  | Texture_pattern of { tpat : patterned; tmap : texture_entry array }
      (** [texture_map], [checker texture {…} texture {…}], [tiles], [average]: [tpat]'s pattern,
          value modifiers and warps (its colour map is unused) pick the entries, which are
          evaluated at the point the pattern saw (its warps applied); [Average] weighs every
          entry by its value *)

  | Material_map of { mimage : bitmap; mwarps : warp list; materials : texture array }
      (** [material_map { IMAGE texture {…} … }]: the image's pixel at the warped point (its palette
          index, or its red times 255) picks one of [materials] (never empty), evaluated at that
          point *)
  | Uv_mapped of { uwarps : warp list; inner : texture }
      (** [texture { uv_mapping … }]: [inner] evaluated at the hit's (u, v, 0); the transforms
          applied to it since ([uwarps]) move no point, they only bend the normals of [inner] (as
          every texture pattern around a normal does) *)

  | Cutaway
      (** no texture of its own in an intersection or difference with [cutaway_textures]: the
          textures of the members of its top-level CSG that the point lies in (a difference: its
          first member's) *)

(** One entry of a texture map: its value (single precision) and texture. *)
and texture_entry = { tvalue : float; ttexture : texture }

(** An interior (§6, §10.1). *)
type interior = {
  ior : float;
  fade_distance : float;
  fade_power : float;
  fade_colour : Rgb.t;
  caustics : float;  (** faked caustics: as stored, 45 times the value written (single precision); 0 without *)
}

(** Geometry. A plane is the set of points P with [normal]·P = [offset], [normal] unit length (§2.3).
    Transforms (§14.4) are baked into a shape's parameters while it has no [trans]; a shape that
    got one (an ellipsoid, a plane under a matrix, any moved mesh) is the object-space shape mapped
    by it. Build moved shapes with [Place.shape], not by hand. *)
type shape =
  | Sphere of { centre : Vec.t; radius : float; trans : Transform.t option; uv_trans : Transform.t option }
      (** §2.2: with [trans], an ellipsoid: the object-space sphere mapped by it. [uv_trans] is
          every modifier applied since the sphere was written, composed (POV-Ray's UV_Trans, which
          Translate_Object and the others keep for every object, besides the centre and radius
          they bake): its UV coordinates are taken in that frame (Sphere::UVCoord) *)
  | Plane of { normal : Vec.t; offset : float; trans : Transform.t option }
      (** §2.3: with [trans], the object-space plane mapped by it (§14.5) *)
  | Triangle of { p1 : Vec.t; p2 : Vec.t; p3 : Vec.t }
      (** §2.4: corners as POV-Ray holds them before its last set-up (P1 and P2 may be swapped by
          an earlier one) *)
  | Smooth_triangle of { p1 : Vec.t; n1 : Vec.t; p2 : Vec.t; n2 : Vec.t; p3 : Vec.t; n3 : Vec.t }
      (** §2.5, vertex normals unit length as parsed, moved by [MTransNormal] since *)
  | Mesh of { mesh : Mesh.t; trans : Transform.t option; textures : texture array }
      (** §2.6: shared mesh data, placed by [trans]; faces with a texture index use [textures] *)
  | Box of { lo : Vec.t; hi : Vec.t; trans : Transform.t option }
      (** §15.1: the corners sorted per axis ([lo] ≤ [hi]); with [trans], the object-space box
          mapped by it *)
  | Cone of {
      p1 : Vec.t;
      r1 : float;
      p2 : Vec.t;
      r2 : float;  (** as written: a cylinder has [r1 = r2] *)
      cylinder : bool;  (** the canonical cylinder [x² + y² ≤ 1, 0 ≤ z ≤ 1] (§15.2) … *)
      dist : float;  (** … else the canonical cone [x² + y² ≤ z², dist ≤ z ≤ 1] (§15.3) *)
      closed : bool;  (** the end caps are part of the surface (no [open]) *)
      trans : Transform.t;  (** canonical space to world: POV-Ray's set-up, then every modifier *)
    }  (** §15.2, §15.3: a cylinder or cone, always placed by a transform (§14.4) *)
  | Disc of {
      centre : Vec.t;
      normal : Vec.t;  (** the unit normal, moved with every modifier (MTransNormal, normalised) *)
      radius : float;
      hole : float;  (** as written (0 without a hole) *)
      trans : Transform.t;  (** canonical space (the disc in z = 0) to world *)
    }  (** §15.4 *)
  | Torus of { major : float; minor : float; sturm : bool; trans : Transform.t }
      (** §15.5: R and r as written, the tube's core circle in the XZ plane, mapped by [trans]
          (a torus always has one: every modifier composes into it, §14.4); [inverse] is
          CSG's, as for every primitive (§16.3) *)
  | Polygon of Polygon.t
      (** §15.7: the outline in its own plane, placed by its transform (its frame, then every
          modifier); flat, with no inside *)
  | Poly of Poly.t
      (** poly.cpp: poly, cubic and quartic, the coefficients as written, placed by the
          transform every modifier composes into; [inverse] is CSG's, as for every primitive *)
  | Quadric of Quadric.t
      (** quadrics.cpp: in world space; every modifier transforms its coefficients and maps its
          box, [inverse] negates the coefficients (and sets [inverted], as POV-Ray's flag) *)
  | Blob of { blob : Blob.t; textures : texture array }
      (** shape/blob.cpp: the components as parsed and moved, the last written first, mapped by
          the blob's transform; [textures] are the components' own textures, which a
          component's [tex] indexes *)
  | Height_field of { field : Hfield.field; trans : Transform.t }
      (** hfield.cpp: the field in its own space (one unit per pixel in x and z, per height step
          in y), mapped by [trans]: Parse_HField's scaling, then every modifier composed into it *)
  | Superellipsoid of Superellipsoid.t
      (** super.cpp: the powers from <e, n>, placed by its transform (every modifier composes
          into it); [inverse] is CSG's *)
  | Ovus of Ovus.t
      (** ovus.cpp: two spheres and the torus part joining them, placed by its transform (every
          modifier composes into it); [inverse] is CSG's *)
  | Sphere_sweep of Sphere_sweep.t
      (** sphsweep.cpp: the modeling spheres, moved by the modifiers until one needs a
          transform; [inverse] is CSG's *)
  | Prism of Prism.t
      (** prism.cpp: the outline's segments in prism space, placed by its transform (every
          modifier composes into it) *)
  | Lathe of Lathe.t  (** lathe.cpp: the rotated spline's segments, placed by its transform *)
  | Sor of Sor.t  (** sor.cpp: the cubic segments of radius², placed by its transform *)
  | Isosurface of Isosurface.t
      (** isosurf.cpp: the function's level set within its container, placed by its transform
          (every modifier composes into it); [inverse] is CSG's (docs/isosurface.md) *)
  | Julia of Julia.t
      (** fractal.cpp: in fractal space, placed by its own transform (every modifier composes
          into it and clears the fractal's own inverted flag); [inverse] toggles that flag *)
  | Parametric of Parametric.t
      (** fpmetric.cpp: three functions of (u, v) within a container, placed by the transform every
          modifier composes into; flat, with no inside ([inverse] does nothing) *)
  | Bicubic of { patch_type : int; u_steps : int; v_steps : int; flatness : float; points : Vec.t array; uv_vectors : float array }
      (** bezier.cpp: the 16 control points in world space (row by row, P[i][j] at 4i + j), which
          every modifier moves; type 0 or 1; flat, with no inside. [uv_vectors]: the texture
          coordinates of the four corners (u0, v0, …, u3, v3; by default (0, 0), (1, 0), (1, 1),
          (0, 1)), which uv_mapping sees *)
  | Csg of { kind : csg_kind; members : member list; box : float array option }
      (** §16: a CSG kept whole (a merge, an intersection or difference, a union with
          [split_union off]); its members are already moved by its transforms and carry the
          texture passed down to them (§16.5). [box] is POV-Ray's box of a union or merge (and
          of the intersection an inverted one becomes) as its history made it: the members'
          single-precision boxes when it was built (CSG::Compute_BBox), then that box's corners
          mapped by each later modifier (Recompute_BBox), which the members' own boxes after the
          same modifiers need not equal ({!Pov_box}); [None] for a box made from the members
          when the CSG is compiled. *)
  | Glyph of { outline : Glyph.outline; depth : float; trans : Transform.t }
      (** §15.9: one letter of a text object (which is a union of its letters): the outline in
          z = 0 extruded to z = [depth], mapped by [trans] (the letter's place in the string, then
          every modifier); [inverse] is CSG's, as for every primitive (§16.3) *)

(** The kinds of CSG after parsing: a difference is an intersection whose later members are
    inverted, and an inverted CSG has been morphed (§16.1, §16.3). [Clipped] is an object with
    [clipped_by]: its first member is the object, the others the clip objects, whose surfaces are
    not seen; the object's hits are kept inside every clip object (§15.8). [Bounded] is an object
    with [bounded_by]: its first member is the object, the others the bounding objects, whose
    surfaces are not seen; a ray meets the object only if it meets every bounding object or starts
    inside it (Ray_In_Bound). [Boxed] is one whose bounding objects POV-Ray removed (a top-level
    primitive, Link_To_Frame): only their box is left, the object's box when it is the smaller. *)
and csg_kind = Union | Merge | Intersection | Clipped | Bounded | Boxed

(** A member of a CSG. *)
and member = {
  mobj : obj;  (** the member, its texture resolved (its own, else its parent's, §16.5) *)
  inverted : bool;
      (** a primitive: its Inside test is negated (§16.3); a CSG: it was inverted, which morphed it
          (its Inside already holds the inversion) and leaves it out of an enclosing
          intersection's bounding box *)
  own_interior : bool;
      (** it has its own [interior {}]: otherwise it SHARES its parent's interior, the same
          interior in interior lists (§16.5); [mobj.interior] then holds the parent's values *)
}

(** A finished object: textured, with an interior (§2.7). *)
and obj = {
  shape : shape;
  texture : texture;
  interior_texture : texture option;  (** the texture seen where a ray meets the surface from inside *)
  uv_mapped : bool;
      (** the object's [uv_mapping]: all its textures are evaluated at the hit's (u, v, 0) *)
  difference : bool;  (** a CSG written as [difference]: [Cutaway] takes its first member's texture *)
  interior : interior;
  no_shadow : bool;
  loc : Loc.t;  (** where the object was written *)
  no_image : bool;  (** §16.6: not hit by image rays (camera rays and what is seen through them) *)
  no_reflection : bool;  (** §16.6: not hit by reflection rays and their descendants *)
  double_illuminate : bool;  (** §16.6: lit from behind too (diffuse with |N·L|) *)
  looks_like : bool;
      (** §19.2: the shape of a light: part of its light's top-level object, not one of its own
          (rays do start inside it, like inside any object: checked against POV-Ray) *)
  shared_interior : int;
      (** a member of a split union that has no [interior {}] of its own: the number of the
          union whose interior it SHARES with its siblings (Post_Process gives the union one
          interior and its members the same one, before the union is split), the same interior
          in interior lists; −1: its own *)
}

(** How a light's intensity depends on where the lit point is (§3.4, §18.2, §18.3). *)
type light_kind =
  | Point_light  (** the same in every direction *)
  | Spotlight  (** a cone around [point_at]: radius and falloff are cosines of angles *)
  | Cylinder_light  (** a beam along [point_at]: radius and falloff are distances from its axis *)

(** A light source (§3.3, §3.4, §10.2, §18.2, §18.3). *)
type light = {
  position : Vec.t;
  colour : Rgb.t;
  shadowless : bool;
  fade_distance : float;
  fade_power : float;
  kind : light_kind;
  parallel : bool;  (** §18.3: every ray arrives along the direction [position] → [point_at] *)
  point_at : Vec.t;  (** moved with the light; <0,0,1> unless written *)
  radius : float;  (** spotlight: cos(radius); cylinder: the radius; 0 for a point light *)
  falloff : float;  (** spotlight: cos(falloff); cylinder: the falloff radius *)
  tightness : float;
}

(** The projection of a camera (§1.4, §18.4). *)
type projection =
  | Perspective  (** rays from [location] through the screen *)
  | Orthographic  (** parallel rays along [direction] from points of the screen *)

(** The camera after §1.3: the vectors used by §1.4. *)
type camera = { location : Vec.t; direction : Vec.t; up : Vec.t; right : Vec.t; projection : projection }

(** How the working colour space maps to the file (§8.1). *)
type gamma = Encode.gamma =
  | Gamma_off  (** legacy scene without assumed_gamma: output = clip(linear) *)
  | Working of float  (** working gamma G (1.0 neutral); the file is sRGB-encoded *)

(** A sky_sphere: its pigments in the order written, its emission and its own transform (§18.1). *)
type sky = { sky_pigments : pigment list; sky_emission : Rgb.t; sky_trans : Transform.t option }

(** The whole scene. *)
type t = {
  camera : camera;
  objects : obj list;  (** in the order written *)
  lights : light list;  (** in the order written *)
  background : Colour.t;  (** as the tracer returns it for missed rays (§8.4) *)
  sky : sky option;
  ambient_light : Rgb.t;
  max_trace_level : int;
  adc_bailout : float;
  version : int;  (** effective language version × 100 (§8.1): 362 without #version *)
  noise_generator : int;  (** [global_settings { noise_generator }]: 1, 2 (the default) or 3 *)
  irid_wavelength : Rgb.t;  (** [global_settings { irid_wavelength }]: <0.70, 0.52, 0.48> by default *)
  gamma : gamma;
  shift : float;
      (** how far the whole scene was moved after it was read (the largest coordinate of the moves
          of {!Place.scene}, 0 for a scene as written): the transforms composed with such a move
          carry the rounding of coordinates that large *)
}
