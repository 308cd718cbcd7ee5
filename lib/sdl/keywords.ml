(* POV-Ray 3.7's reserved words (parser/reswords.cpp) as povml treats them: one table, whose
   word lists below are its rows grouped by status. *)

type status = Read | Object | Not_supported | Object_not_supported | Reserved

(* The words that start an object povml reads: its shapes, CSG and object (docs/povray-rules.md
   §14–§16; cubic is a pattern too); [Objects] reads each. A new shape's keyword goes here. *)
let objects =
  [ "sphere"; "box"; "cylinder"; "cone"; "disc"; "torus"; "plane"; "object"; "triangle";
    "smooth_triangle"; "mesh"; "mesh2"; "union"; "merge"; "intersection"; "difference"; "text";
    "polygon"; "quadric"; "cubic"; "quartic"; "poly"; "polynomial"; "blob"; "height_field";
    "superellipsoid"; "ovus"; "sphere_sweep"; "prism"; "lathe"; "sor"; "julia_fractal"; "bicubic_patch";
    "parametric"; "isosurface" ]

(* Objects povml does not render yet: inside a union too they are "not supported yet". *)
let objects_not_supported = [ "composite" ]

(* The other words this interpreter reads. *)
let read =
  [ "adc_bailout"; "ambient"; "ambient_light"; "angle"; "assumed_gamma"; "background"; "blue"; "brilliance";
    "camera"; "clock"; "color"; "colour"; "conserve_energy"; "diffuse"; "direction"; "emission"; "exponent";
    "fade_color"; "fade_colour"; "fade_distance"; "fade_power"; "falloff"; "false"; "filter"; "finish"; "fresnel";
    "global_settings"; "gray"; "grey"; "green"; "hollow"; "image_height"; "image_width"; "interior"; "ior";
    "light_source"; "location"; "look_at"; "max_trace_level"; "metallic"; "no"; "no_shadow"; "off";
    "on"; "perspective"; "phong"; "phong_size"; "pi"; "pigment"; "red"; "reflection";
    "reflection_exponent"; "refraction"; "rgb"; "rgbf"; "rgbft"; "rgbt"; "right"; "roughness"; "shadowless";
    "sky"; "sky_sphere"; "specular"; "t"; "texture"; "translate"; "transmit"; "true"; "u"; "up"; "v";
    "version"; "x"; "y"; "yes"; "z"; "albedo"; "charset"; "number_of_waves"; "noise_generator";
    "irid_wavelength"; "quick_color"; "quick_colour"; "abs"; "sqrt"; "sqr"; "sin"; "cos"; "tan"; "asin"; "acos";
    "atan"; "atan2"; "pow"; "exp"; "ln"; "log"; "min"; "max"; "int"; "floor"; "ceil"; "mod"; "div"; "radians";
    "degrees"; "vlength"; "vnormalize"; "vdot"; "vcross"; "select"; "vertex_vectors"; "normal_vectors"; "uv_vectors"; "texture_list"; "face_indices"; "normal_indices";
    "uv_indices"; "inside_vector"; "no_image"; "no_reflection"; "double_illuminate"; "spotlight";
    "parallel"; "point_at"; "radius"; "tightness"; "orthographic"; "looks_like";
    "open"; "inverse"; "split_union"; "clipped_by"; "ttf"; "reciprocal";
    "material"; "texture_map"; "interior_texture"; "tiles"; "irid"; "uv_mapping"; "crand"; "image_map"; "bump_map"; "image_pattern"; "caustics"; "cutaway_textures"; "pigment_pattern";
    "bounded_by"; "trace"; "inside"; "min_extent"; "max_extent" ]
  (* pigment patterns (docs/povray-rules.md §17) *)
  @ [ "checker"; "gradient"; "hexagon"; "brick"; "brick_size"; "mortar"; "color_map"; "colour_map"; "frequency";
      "phase"; "ramp_wave"; "triangle_wave"; "sine_wave"; "scallop_wave"; "cubic_wave"; "poly_wave"; "pigment_map" ]
  (* the other patterns, their modifiers, warps and normals *)
  @ [ "agate"; "agate_turb"; "aoi"; "average"; "boxed"; "bozo"; "bumps"; "cells"; "control0"; "control1"; "crackle"; "cylindrical"; "dents"; "facets"; "granite"; "julia"; "leopard"; "magnet"; "mandel"; "marble"; "onion";
      "pavement"; "planar"; "quilted"; "radial"; "ripples"; "slope"; "spherical"; "spiral1"; "spiral2"; "spotted";
      "square"; "tiling"; "triangular"; "waves"; "wood"; "wrinkles"; "turbulence"; "octaves"; "omega"; "lambda";
      "warp"; "form"; "metric"; "offset"; "solid"; "coords"; "size"; "exterior"; "number_of_sides";
      "number_of_tiles"; "pattern"; "repeat"; "flip"; "black_hole"; "strength"; "type"; "orientation"; "dist_exp";
      "toroidal"; "major_radius"; "altitude"; "normal"; "bump_size"; "accuracy"; "no_bump_scale"; "slope_map";
      "normal_map" ]
  (* sRGB colours, and POV-Ray 3.7's reserved words povml reads outside these lists: functions,
     charset names, #fopen and #write words, declaration modifiers (parser/reswords.cpp) *)
  @ [ "srgb"; "srgbf"; "srgbt"; "srgbft"; "acosh"; "asinh"; "atanh"; "asc"; "bitwise_and"; "bitwise_or"; "bitwise_xor";
      "chr"; "clock_on"; "concat"; "cosh"; "defined"; "dimension_size"; "dimensions"; "file_exists"; "now"; "rand";
      "seed"; "sinh"; "str"; "strcmp"; "strlen"; "strlwr"; "strupr"; "substr"; "tanh"; "val"; "vaxis_rotate";
      "vrotate"; "vstr"; "array"; "ascii"; "utf8"; "sys"; "append"; "deprecated"; "once"; "internal"; "function"; "spline"; "sint8";
      "sint16be"; "sint16le"; "sint32be"; "sint32le"; "uint8"; "uint16be"; "uint16le"; "hf_gray_16"; "mm_per_unit";
      "max_intersections"; "dtag"; "no_radiosity"; "importance"; "target"; "pass_through"; "collect"; "hierarchy";
      "bokeh"; "confidence"; "variance"; "aperture"; "focal_point"; "blur_samples"; "alpha" ]

(* Words povml will read later: meeting one is a located "not supported yet". *)
let not_supported =
  [ "rotate"; "scale"; "matrix"; "transform";
    "area_light";
    "projected_through"; "fisheye"; "panoramic"; "ultra_wide_angle"; "omnimax";
    "radiosity"; "photons";
    "media"; "fog"; "rainbow"; "dispersion"; "dispersion_samples";
    "subsurface";
    "light_group"; "sturm";
    "phong_albedo"; "metallic_albedo"; "translucency" ]
  (* patterns and pattern modifiers not read yet (docs/povray-rules.md §17) *)
  @ [ "density_file"; "color_list" ]
  (* more of POV-Ray 3.7's reserved words that start something povml does not read, each found
     where POV-Ray reads it in an object, a light_source, a texture or an expression (checked word
     by word with POV-Ray: parser/reswords.cpp) *)
  @ [ "mesh_camera"; "adaptive"; "area_illumination"; "circular"; "jitter";
      "orient"; "media_attenuation"; "media_interaction"; "material_map"; "density"; "density_map";
      "datetime" ]

(* The rest of POV-Ray 3.7's reserved words (parser/reswords.cpp), none of which povml reads: words
   inside blocks povml does not read yet, or reads only where they belong (a fog's fog_type, an
   isosurface's accuracy, the sums and products of a user function …). They cannot
   be declared, as in POV-Ray; found out of place they are the user's error, as they are POV-Ray's
   (POV-Ray lets sred, sgreen, sblue and global be declared: they are not in this list). *)
let reserved =
  [ "aa_level"; "aa_threshold"; "absorption"; "all"; "all_intersections"; "always_sample"; "anisotropy";
    "arc_angle"; "autostop"; "b_spline"; "bezier_spline"; "bmp"; "component"; "conic_sweep"; "contained_by";
    "cube"; "cubic_spline"; "df3"; "distance"; "eccentricity"; "evaluate"; "expand_thresholds"; "exr";
    "extinction"; "falloff_angle"; "flatness"; "fog_alt"; "fog_offset"; "fog_type"; "gamma"; "gather"; "gif";
    "global_lights"; "hdr"; "hypercomplex"; "iff"; "interpolate"; "intervals"; "jpeg"; "linear_spline";
    "linear_sweep"; "load_file"; "map_type"; "max_gradient"; "max_iteration"; "max_sample"; "max_trace"; "method";
    "natural_spline"; "pgm"; "png"; "pot"; "ppm"; "precision"; "precompute"; "premultiplied"; "pretrace_end";
    "pretrace_start"; "prod"; "sum"; "pwr"; "quadratic_spline"; "quaternion"; "ratio"; "samples"; "save_file";
    "scattering"; "slice"; "smooth"; "spacing"; "steps"; "tga"; "thickness"; "threshold"; "tiff"; "tile2";
    "tolerance"; "turb_depth"; "u_steps"; "use_alpha"; "use_color"; "use_colour"; "use_index"; "v_steps";
    "water_level"; "width"; "xyz" ]

let table =
  List.concat
    [ List.map (fun w -> (w, Object)) objects;
      List.map (fun w -> (w, Read)) read;
      List.map (fun w -> (w, Not_supported)) not_supported;
      List.map (fun w -> (w, Object_not_supported)) objects_not_supported;
      List.map (fun w -> (w, Reserved)) reserved ]

let words keep = List.filter_map (fun (w, s) -> if keep s then Some w else None) table
