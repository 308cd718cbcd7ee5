(* Unit tests of the povml library: one group per module. The "POV-Ray source rules" groups hold
   behaviours first found missing by these tests (optional commas, a second camera or assumed_gamma,
   \uXXXX escapes, the version a background sees). *)

let () =
  Alcotest.run "povml"
    ([
      ("Vec", Test_vec.tests);
      ("Floats", Test_floats.tests);
      ("Lexer", Test_lexer.tests);
      ("Syntax (POV-Ray 3.7 forms)", Test_syntax.tests);
      ("Interp", Test_interp.tests);
      ("Value", Test_misc.tests_value);
      ("Suggest", Test_misc.tests_suggest);
      ("Colour", Test_misc.tests_colour);
      ("Defaults", Test_misc.tests_defaults);
      ("Error", Test_misc.tests_error);
      ("Triangle", Test_triangle.tests);
      ("Mesh", Test_mesh.tests @ Test_mesh.trace_tests);
      ("Bvh", Test_bvh.tests);
      ("Transform", Test_transform.tests);
      ("Compile", Test_compile.tests);
      ("Box", Test_box.tests);
      ("Lights, orthographic camera, flags", Test_lights.tests);
      ("Quadrics", Test_quadrics.tests);
      ("Quadric (quadric { })", Test_quadric.tests);
      ("Polygon", Test_polygon.tests);
      ("Polysolv", Test_polysolv.tests);
      ("Torus", Test_torus.tests);
      ("Blob", Test_blob.tests);
      ("Height field", Test_hfield.tests);
      ("Prism, lathe, sor", Test_spline.tests);
      ("Spline values (spline { })", Test_spline_values.tests);
      ("Julia fractal", Test_julia.tests);
      ("Fn_budget", Test_fn_budget.tests);
      ("Isosurface", Test_isosurface.tests);
      ("Bicubic patch", Test_bezier.tests);
      ("Parametric surface", Test_parametric.tests);
      ("Poly (poly, cubic, quartic)", Test_poly.tests);
      ("UV coordinates and uv_mapping", Test_uv.tests);
      ("Sphere normal", Test_sphere_normal.tests);
      ("Text", Test_text.tests);
      ("CSG", Test_csg.tests);
      ("Probe (trace, inside, extents)", Test_probe.tests);
      ("Patterns", Test_patterns.tests);
      ("Textures (layers, maps, materials)", Test_textures.tests);
      ("pattern values", Test_pattern_values.tests);
      ("pattern values (surface)", Test_pattern_values.surface_tests);
      ("pattern values (noise)", Test_pattern_values.noise_tests);
      ("Noise", Test_noise.tests);
      ("Internal functions (functions.inc)", Test_fn_internal.tests);
      ("Warp", Test_warp.tests);
      ("Trace", Test_trace.tests);
      ("Render", Test_render.tests);
      ("Jitter", Test_jitter.tests);
      ("Stats", Test_misc.tests_stats);
      ("Image", Test_misc.tests_image);
      ("Encode", Test_encode.tests);
      ("Compare", Test_compare.tests);
      ("Check and report", Test_check.tests);
      ("Output", Test_misc.tests_output);
      ("Pipeline", Test_misc.tests_pipeline);
      ("Access and user files", Test_user_files.tests);
      ("Robust mode", Test_robust.tests);
      ("Language properties (qcheck)", Test_lang_props.tests);
      ("POV-Ray source rules (Lexer)", Test_lexer.source_rules);
      ("POV-Ray source rules (Interp)", Test_interp.source_rules);
      ("Interrupt", Test_interrupt.tests);
      ("Whole_file", Test_whole_file.tests);
      ("Normals (perturbed normals)", Test_normals.tests);
      ("Images (image_map, image_pattern, bump_map)", Test_images.tests);
      ("Decoders against hostile files", Test_decoders.tests);
      ("Superellipsoid, ovus, sphere_sweep", Test_superq.tests);
      ("Shape kinds (traits)", Test_traits.tests);
    ])
