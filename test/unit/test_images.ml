(* Images: the decoders (known pixels of the project's images in scenes/images/) and image_map
   and image_pattern lookups against the values POV-Ray 3.7.0.10 prints for
   test/unit/data/images.pov (16 decimals; the colours are single precision, so they must agree
   to the last digit). *)

open Helpers

(* the repository's root: the directory above the working directory that holds scenes/images *)
let root =
  let rec up d n =
    if Sys.file_exists (Filename.concat d "scenes/images/rgb8.png") then d
    else if n = 0 then Alcotest.fail "scenes/images not found above the working directory"
    else up (Filename.dirname d) (n - 1)
  in
  lazy (up (Sys.getcwd ()) 8)

let image name = Filename.concat (Lazy.force root) ("scenes/images/" ^ name)

let raw : Image_file.options =
  { gamma_correct = false; default_gamma = None; working_gamma = Neutral; gamma_override = false; premultiply = None; max_pixels = 8192 * 8192; max_memory_mb = 4096 }

let read fmt name = match Image_read.read fmt raw (image name) with Ok i -> i | Error m -> Alcotest.fail (Image_read.message m)

(* the generator of scenes/images' base picture (an 8-bit PPM): each pixel's r, g, b *)
let base x y = ((x * 16) + 8, (y * 21) + 5, (((x / 4) * 60) + ((y / 4) * 90) + 13) mod 256)

let check_base ?(bottom_up = false) what (img : Image_file.t) =
  Alcotest.(check (pair int int)) (what ^ ": size") (16, 12) (img.width, img.height);
  List.iter
    (fun (x, y) ->
      let r, g, b = base x y in
      let r', g', b', _, _ = Image_file.rgbft img x (if bottom_up then 11 - y else y) in
      float_eq ~eps:0. (Printf.sprintf "%s red at %d,%d" what x y) (Precision.f32 (float_of_int r /. 255.)) r';
      float_eq ~eps:0. (Printf.sprintf "%s green at %d,%d" what x y) (Precision.f32 (float_of_int g /. 255.)) g';
      float_eq ~eps:0. (Printf.sprintf "%s blue at %d,%d" what x y) (Precision.f32 (float_of_int b /. 255.)) b')
    [ (0, 0); (15, 0); (7, 5); (3, 11); (15, 11) ]

let decoders =
  [
    Alcotest.test_case "8-bit RGB PNG: the file's integers" `Quick (fun () -> check_base "rgb8.png" (read Png "rgb8.png"));
    Alcotest.test_case "interlaced PNG: Adam7 passes" `Quick (fun () -> check_base "interlaced.png" (read Png "interlaced.png"));
    Alcotest.test_case "PNG without chunks, with sRGB" `Quick (fun () ->
        check_base "nogamma.png" (read Png "nogamma.png");
        check_base "srgb.png" (read Png "srgb.png"));
    Alcotest.test_case "PPM and TGA" `Quick (fun () ->
        check_base "img.ppm" (read Ppm "img.ppm");
        (* ImageMagick wrote the rows top first but left the header's origin bit at bottom-left,
           which POV-Ray's reader obeys (the fidelity scene image_tga agrees with it) *)
        check_base ~bottom_up:true "img.tga" (read Tga "img.tga"));
    Alcotest.test_case "16-bit PNG keeps 16 bits" `Quick (fun () ->
        let img = read Png "rgb16.png" in
        match img.pixels with
        | Colour { max = 65535; rgb; _ } ->
            (* the generator: r = (x·4096 + 1234·y + 77) mod 65536 *)
            Alcotest.(check int) "red at 3,2" (((3 * 4096) + (1234 * 2) + 77) mod 65536) rgb.(3 * (3 + (2 * 16)))
        | _ -> Alcotest.fail "not a 16-bit RGB image");
    Alcotest.test_case "palette PNG and GIF keep their indices" `Quick (fun () ->
        List.iter
          (fun (fmt, name) ->
            let img = read fmt name in
            Alcotest.(check bool) (name ^ " indexed") true (Image_file.is_indexed img);
            Alcotest.(check bool) (name ^ " palette size") true (Image_file.colour_map_size img > 16);
            (* the picture's red grows to the right, through the palette's reduction *)
            let r0, _, _, _, _ = Image_file.rgbft img 0 0 and r1, _, _, _, _ = Image_file.rgbft img 15 0 in
            Alcotest.(check bool) (name ^ " red grows to the right") true (r1 > r0 +. 0.5))
          [ (Image_file.Png, "pal.png"); (Gif, "img.gif") ]);
    Alcotest.test_case "RGBA PNG: alpha as transmit" `Quick (fun () ->
        let img = read Png "alpha.png" in
        Alcotest.(check bool) "has transparency" true (Image_file.has_transparency img);
        Alcotest.(check bool) "not opaque" false (Image_file.is_opaque img);
        (* alpha: 255 left of x = 8, (x·y·9) mod 256 right of it *)
        let _, _, _, _, t = Image_file.rgbft img 10 3 in
        float_eq ~eps:0. "transmit at 10,3" (Precision.f32 (1. -. Precision.f32 (float_of_int (10 * 3 * 9 mod 256) /. 255.))) t);
    Alcotest.test_case "a missing or broken file is an error, not an exception" `Quick (fun () ->
        (match Image_read.read Png raw "/nonexistent/x.png" with Ok _ -> Alcotest.fail "read" | Error _ -> ());
        match Image_read.read Png raw (image "img.ppm") with Ok _ -> Alcotest.fail "a PPM read as PNG" | Error _ -> ());
    Alcotest.test_case "sRGB decoding in single precision" `Quick (fun () ->
        (* 128/255 decoded by SRGBGammaCurve::Decode: POV-Ray prints (srgb 128/255).red as
           0.21586053073406219482 *)
        float_eq ~eps:1e-17 "sRGB 128" 0.21586053073406219482 (Gamma_curve.decode Srgb (Precision.f32 (128. /. 255.))));
  ]

(* POV-Ray's values: image block, probe number, red, green, blue, filter, transmit *)
let povray_values =
  [
    ("rgb8", 0, [| 0.0004925411776640; 0.0001751390664140; 0.0014332280261442; 0.0000000000000000; 0.0000000000000000 |]);
    ("rgb8", 1, [| 0.2508437037467957; 0.1572836190462112; 0.7445323467254639; 0.0000000000000000; 0.0000000000000000 |]);
    ("rgb8", 2, [| 0.5859761238098145; 0.6870334148406982; 0.1801473647356033; 0.0000000000000000; 0.0000000000000000 |]);
    ("rgb8", 3, [| 0.4877687096595764; 0.0545938611030579; 0.2388314157724380; 0.0000000000000000; 0.0000000000000000 |]);
    ("rgb16_bilinear", 0, [| 0.0193558167666197; 0.1170201674103737; 0.0573098734021187; 0.0000000000000000; 0.0000000000000000 |]);
    ("rgb16_bilinear", 1, [| 0.2955447137355804; 0.1860829591751099; 0.4276365935802460; 0.0000000000000000; 0.0000000000000000 |]);
    ("rgb16_bilinear", 2, [| 0.8505467772483826; 0.6823023557662964; 0.0673001036047935; 0.0000000000000000; 0.0000000000000000 |]);
    ("rgb16_bilinear", 3, [| 0.4954760968685150; 0.0489311814308167; 0.1980869621038437; 0.0000000000000000; 0.0000000000000000 |]);
    ("pal_normdist", 0, [| 0.0352956354618073; 0.0354058928787708; 0.0276180878281593; 0.0000000000000000; 0.0000000000000000 |]);
    ("pal_normdist", 1, [| 0.1888644397258759; 0.2367442399263382; 0.6186490654945374; 0.0000000000000000; 0.0000000000000000 |]);
    ("pal_normdist", 2, [| 0.7309054732322693; 0.6865794062614441; 0.1711544692516327; 0.0000000000000000; 0.0000000000000000 |]);
    ("pal_normdist", 3, [| 0.3586575984954834; 0.0526326857507229; 0.2388314157724380; 0.0000000000000000; 0.0000000000000000 |]);
    ("grey", 0, [| 0.0000000000000000; 0.0000000000000000; 0.0000000000000000; 0.0000000000000000; 0.0000000000000000 |]);
    ("grey", 1, [| 0.2000000029802322; 0.2000000029802322; 0.2000000029802322; 0.0000000000000000; 0.0000000000000000 |]);
    ("grey", 2, [| 0.6117647290229797; 0.6117647290229797; 0.6117647290229797; 0.0000000000000000; 0.0000000000000000 |]);
    ("grey", 3, [| 0.1176470592617989; 0.1176470592617989; 0.1176470592617989; 0.0000000000000000; 0.0000000000000000 |]);
    ("alpha_once", 0, [| 0.0004925411776640; 0.0001751390664140; 0.0014332280261442; 0.0000000000000000; 0.0000000000000000 |]);
    ("alpha_once", 1, [| 0.2508437037467957; 0.1572836190462112; 0.7445323467254639; 0.0000000000000000; 0.5921568870544434 |]);
    ("alpha_once", 2, [| 0.5859761238098145; 0.6870334148406982; 0.1801473647356033; 0.0000000000000000; 0.7803921699523926 |]);
    ("alpha_once", 3, [| 1.0000000000000000; 1.0000000000000000; 1.0000000000000000; 0.0000000000000000; 1.0000000000000000 |]);
    ("jpeg", 0, [| 0.0027317430358380; 0.0009105809731409; 0.0040247170254588; 0.0000000000000000; 0.0000000000000000 |]);
    ("jpeg", 1, [| 0.2383976578712463; 0.1441284865140915; 0.7835379242897034; 0.0000000000000000; 0.0000000000000000 |]);
    ("jpeg", 2, [| 0.5906189084053040; 0.7011020183563232; 0.1844749897718430; 0.0000000000000000; 0.0000000000000000 |]);
    ("jpeg", 3, [| 0.4677838385105133; 0.0561284944415092; 0.2704978585243225; 0.0000000000000000; 0.0000000000000000 |]);
    ("gif_ft", 0, [| 0.0144438436254859; 0.0103298230096698; 0.0040247170254588; 0.2500000000000000; 0.0000000000000000 |]);
    ("gif_ft", 1, [| 0.3515326976776123; 0.1274376958608627; 0.7379105687141418; 0.2500000000000000; 0.0000000000000000 |]);
    ("gif_ft", 2, [| 0.7454043626785278; 0.6795425415039062; 0.1778884083032608; 0.2500000000000000; 0.0000000000000000 |]);
    ("gif_ft", 3, [| 0.3515326976776123; 0.0578054338693619; 0.2345506548881531; 0.2500000000000000; 0.0000000000000000 |]);
    ("pattern", 0, [| 0.1195229217410088; 0.1195229217410088; 0.1195229217410088; 0.0000000000000000; 0.0000000000000000 |]);
    ("pattern", 1, [| 0.5136960744857788; 0.5136960744857788; 0.5136960744857788; 0.0000000000000000; 0.0000000000000000 |]);
    ("pattern", 2, [| 0.7748364806175232; 0.7748364806175232; 0.7748364806175232; 0.0000000000000000; 0.0000000000000000 |]);
    ("pattern", 3, [| 0.4242706894874573; 0.4242706894874573; 0.4242706894874573; 0.0000000000000000; 0.0000000000000000 |]);
    ("ppm_bicubic", 0, [| 0.0407511852681637; 0.1035973057150841; 0.1256570667028427; 0.0000000000000000; 0.0000000000000000 |]);
    ("ppm_bicubic", 1, [| 0.5019608139991760; 0.4725490212440491; 0.7568627595901489; 0.0000000000000000; 0.0000000000000000 |]);
    ("ppm_bicubic", 2, [| 0.7730196118354797; 0.8453915119171143; 0.4275002181529999; 0.0000000000000000; 0.0000000000000000 |]);
    ("ppm_bicubic", 3, [| 0.7027451395988464; 0.2650196254253387; 0.5001762509346008; 0.0000000000000000; 0.0000000000000000 |]);
    ("tga_spherical", 0, [| 0.0024282159283757; 0.8387991189956665; 0.5332764983177185; 0.0000000000000000; 0.0000000000000000 |]);
    ("tga_spherical", 1, [| 0.0024282159283757; 0.5394796133041382; 0.5332764983177185; 0.0000000000000000; 0.0000000000000000 |]);
    ("tga_spherical", 2, [| 0.0024282159283757; 0.2269658893346786; 0.1356333494186401; 0.0000000000000000; 0.0000000000000000 |]);
    ("tga_spherical", 3, [| 0.2462013959884644; 0.6795425415039062; 0.0409151986241341; 0.0000000000000000; 0.0000000000000000 |]);
  ]

let blocks =
  [
    ("rgb8", "image_map { png \"scenes/images/rgb8.png\" }");
    ("rgb16_bilinear", "image_map { png \"scenes/images/rgb16.png\" interpolate 2 }");
    ("pal_normdist", "image_map { png \"scenes/images/pal.png\" interpolate 4 }");
    ("grey", "image_map { png \"scenes/images/grey.png\" }");
    ("alpha_once", "image_map { png \"scenes/images/alpha.png\" once }");
    ("jpeg", "image_map { jpeg \"scenes/images/img.jpg\" }");
    ("gif_ft", "image_map { gif \"scenes/images/img.gif\" transmit 3, 0.5 filter all 0.25 }");
    ("pattern", "image_pattern { png \"scenes/images/rgb8.png\" interpolate 2 }");
    ("ppm_bicubic", "image_map { ppm \"scenes/images/img.ppm\" interpolate 3 }");
    ("tga_spherical", "image_map { tga \"scenes/images/img.tga\" map_type 1 }");
  ]

let probes = [| Vec.make 0.03 0.97 0.; Vec.make 0.5 0.5 0.; Vec.make 0.77 0.123 0.; Vec.make (-1.3) 2.71 0. |]

(* [s] with every [sub] replaced by [by] *)
let replace s ~sub ~by =
  let b = Buffer.create (String.length s) and n = String.length sub in
  let rec go i =
    if i > String.length s - n then Buffer.add_string b (String.sub s i (String.length s - i))
    else if String.sub s i n = sub then (Buffer.add_string b by; go (i + n))
    else (Buffer.add_char b s.[i]; go (i + 1))
  in
  go 0;
  Buffer.contents b

let pigment_of_block block =
  let root = Lazy.force root in
  let opts = { opts with access = Access.allow_read opts.access root } in
  let text = Printf.sprintf "#version 3.7;\nglobal_settings { assumed_gamma 1 }\nplane { z, 0 pigment { %s } }\n" block in
  (* the file names are relative to the repository's root, as POV-Ray ran there *)
  let text = replace text ~sub:"\"scenes/" ~by:("\"" ^ root ^ "/scenes/") in
  let s, _ = Interp.load_string opts ~file:"t.pov" text in
  (layer_of (List.hd s.objects)).pigment

let lookups =
  List.map
    (fun (name, block) ->
      Alcotest.test_case ("image lookups: " ^ name) `Quick (fun () ->
          let pg = pigment_of_block block in
          List.iter
            (fun (n, i, v) ->
              if n = name then begin
                let c, _ = Pigment.colour_found 2 pg Patterns.no_hit probes.(i) in
                let got = [| c.Colour.red; c.green; c.blue; c.filter; c.transmit |] in
                Array.iteri (fun k e -> float_eq ~eps:1e-15 (Printf.sprintf "%s probe %d channel %d" name i k) e got.(k)) v
              end)
            povray_values))
    blocks

let found =
  [
    Alcotest.test_case "once: no colour found off the image, the clear colour" `Quick (fun () ->
        let pg = pigment_of_block "image_map { png \"scenes/images/alpha.png\" once }" in
        Alcotest.(check bool) "may miss" true (Pigment.may_miss pg);
        Alcotest.(check bool) "not opaque" false (Pigment.opaque pg);
        let c, f = Pigment.colour_found 2 pg Patterns.no_hit (Vec.make 2. 2. 0.) in
        Alcotest.(check bool) "found" false f;
        colour_eq "clear" (colour5 1. 1. 1. 0. 1.) c;
        let _, f = Pigment.colour_found 2 pg Patterns.no_hit (Vec.make 0.5 0.5 0.) in
        Alcotest.(check bool) "found on it" true f);
    Alcotest.test_case "a repeated opaque image_map is opaque and never misses" `Quick (fun () ->
        let pg = pigment_of_block "image_map { png \"scenes/images/rgb8.png\" }" in
        Alcotest.(check bool) "may miss" false (Pigment.may_miss pg);
        Alcotest.(check bool) "opaque" true (Pigment.opaque pg));
    Alcotest.test_case "a missing image file is a located error naming it" `Quick (fun () ->
        expect_scene_error "missing" "plane { z, 0 pigment { image_map { png \"no_such.png\" } } }" ~line:1 ~col:36 ~sub:"no_such.png");
    Alcotest.test_case "bump_map outside a normal is an error" `Quick (fun () ->
        expect_scene_error "bump_map" "plane { z, 0 pigment { bump_map { png \"x.png\" } } }" ~line:1 ~col:24 ~sub:"bump_map");
    Alcotest.test_case "iff images are not supported yet" `Quick (fun () ->
        expect_scene_error "iff" "plane { z, 0 pigment { image_map { iff \"x.iff\" } } }" ~line:1 ~col:36 ~sub:"not supported yet");
  ]

let tests = decoders @ lookups @ found
