(* The decoders' defences against hostile files (issue 34): overflow-safe sizes, the caps, the
   inflate bound, PNG's CRCs and IHDR rules, GIF's code sizes, PPM's ASCII numbers as POV-Ray's
   atoi stores them. *)

let options : Image_file.options =
  { gamma_correct = false; default_gamma = None; working_gamma = Neutral; gamma_override = false; premultiply = None; max_pixels = 1 lsl 20; max_memory_mb = 64 }

let be32 n = String.init 4 (fun i -> Char.chr ((n lsr (8 * (3 - i))) land 0xff))
let le16 n = String.init 2 (fun i -> Char.chr ((n lsr (8 * i)) land 0xff))
let chunk ?(crc_delta = 0) kind body = be32 (String.length body) ^ kind ^ body ^ be32 (Png_text.crc (kind ^ body) lxor crc_delta)

(* a zlib stream of [data] in one stored block *)
let stored data = "\x78\x01\001" ^ le16 (String.length data) ^ le16 (String.length data lxor 0xffff) ^ data ^ "\000\000\000\000"

let png ?(depth = 8) ?(ctype = 2) ?(extra = []) w h idat =
  "\137PNG\r\n\026\n"
  ^ chunk "IHDR" (be32 w ^ be32 h ^ String.make 1 (Char.chr depth) ^ String.make 1 (Char.chr ctype) ^ "\000\000\000")
  ^ String.concat "" extra ^ chunk "IDAT" idat ^ chunk "IEND" ""

let refused what f =
  match f () with
  | (_ : Image_file.t) -> Alcotest.failf "%s: decoded" what
  | exception Image_file.Bad _ -> ()
  | exception Image_file.Over_limit _ -> ()

let bad_message what expected f =
  match f () with
  | (_ : Image_file.t) -> Alcotest.failf "%s: decoded" what
  | exception Image_file.Bad m -> Alcotest.(check string) what expected m

let tests =
  [
    Alcotest.test_case "sizes multiply without wrapping round" `Quick (fun () ->
        Alcotest.(check int) "small" 12 (Image_file.mul 3 4);
        Alcotest.(check int) "zero" 0 (Image_file.mul 0 max_int);
        Alcotest.(check int) "overflow" max_int (Image_file.mul (1 lsl 61) 4);
        Alcotest.(check int) "overflow of a product" max_int (Image_file.mul (Image_file.mul (1 lsl 40) (1 lsl 40)) 3));
    Alcotest.test_case "sizes against the pixel and memory caps" `Quick (fun () ->
        Image_file.check_size options ~format:"PNG" ~width:1024 ~height:1024 ~samples:4;
        (match Image_file.check_size options ~format:"PNG" ~width:1025 ~height:1024 ~samples:1 with
        | () -> Alcotest.fail "above the pixel cap"
        | exception Image_file.Over_limit { option; _ } -> Alcotest.(check string) "option" "--max-pixels N" option);
        match Image_file.check_size { options with max_memory_mb = 16 } ~format:"PNG" ~width:1024 ~height:1024 ~samples:4 with
        | () -> Alcotest.fail "above the memory cap"
        | exception Image_file.Over_limit { option; _ } -> Alcotest.(check string) "option" "--max-memory MIB" option);
    Alcotest.test_case "inflate stops at its limit" `Quick (fun () ->
        (* 65,535 zero bytes stored, asked for 100 *)
        let z = stored (String.make 65535 '\000') in
        Alcotest.(check int) "limited" 100 (String.length (Inflate.zlib ~limit:100 z));
        Alcotest.(check int) "whole" 65535 (String.length (Inflate.zlib z)));
    Alcotest.test_case "PNG: data past the promised size is ignored, as libpng does" `Quick (fun () ->
        let img = Png_file.read_png options (png 1 1 (stored ("\000\010\020\030" ^ String.make 60000 '\255'))) in
        Alcotest.(check int) "width" 1 img.width;
        let r, g, b, _, _ = Image_file.rgbft img 0 0 in
        Alcotest.(check (list (float 0.))) "pixel" [ Precision.f32 (10. /. 255.); Precision.f32 (20. /. 255.); Precision.f32 (30. /. 255.) ] [ r; g; b ]);
    Alcotest.test_case "PNG: CRCs and IHDR as libpng checks them" `Quick (fun () ->
        let px = stored "\000\010\020\030" in
        bad_message "bad IDAT CRC" "the PNG's IDAT chunk is damaged (its CRC does not match its data)" (fun () ->
            Png_file.read_png options
              ("\137PNG\r\n\026\n" ^ chunk "IHDR" (be32 1 ^ be32 1 ^ "\008\002\000\000\000") ^ chunk ~crc_delta:1 "IDAT" px ^ chunk "IEND" ""));
        (* an ancillary chunk with a bad CRC is dropped: its gamma is not used *)
        let with_gama = png ~extra:[ chunk ~crc_delta:1 "gAMA" (be32 100000) ] 1 1 px in
        ignore (Png_file.read_png options with_gama);
        bad_message "depth 3" "the PNG's bit depth 3 is not 1, 2, 4, 8 or 16" (fun () -> Png_file.read_png options (png ~depth:3 1 1 px));
        bad_message "RGB at 4 bits" "the PNG's bit depth 4 is not allowed with its colour type 2" (fun () ->
            Png_file.read_png options (png ~depth:4 1 1 px));
        bad_message "no pixels" "the PNG's size 0×1 has no pixels" (fun () -> Png_file.read_png options (png 0 1 px));
        refused "above the cap" (fun () -> Png_file.read_png options (png 2048 2048 px)));
    Alcotest.test_case "GIF: LZW code sizes 2 to 9 (gifdecod.cpp)" `Quick (fun () ->
        let gif code_size =
          "GIF89a" ^ le16 1 ^ le16 1 ^ "\x80\000\000" ^ "\255\000\000\000\000\255" ^ "," ^ le16 0 ^ le16 0 ^ le16 1 ^ le16 1 ^ "\000"
          ^ String.make 1 (Char.chr code_size) ^ "\002\004\005\000;"
        in
        bad_message "13" "the GIF's LZW code size 13 is above 9" (fun () -> Gif_file.read_gif options (gif 13));
        bad_message "1" "the GIF's LZW code size 1 is below 2" (fun () -> Gif_file.read_gif options (gif 1));
        bad_message "0×0" "the GIF's image is 0×0 pixels: it has none" (fun () ->
            Gif_file.read_gif options ("GIF89a" ^ le16 0 ^ le16 0 ^ "\x80\000\000" ^ "\255\000\000\000\000\255" ^ "," ^ String.make 8 '\000' ^ "\000\002\000;")));
    Alcotest.test_case "PPM: ASCII numbers wrap as POV-Ray stores them" `Quick (fun () ->
        (* 300 in an 8-bit container is 300 mod 256; a number longer than any int is all ones *)
        let img = Netpbm_file.read_netpbm ~colour:false options "P2\n2 1\n255\n300 99999999999999999999999999\n" in
        let g0, _, _, _, _ = Image_file.rgbft img 0 0 and g1, _, _, _, _ = Image_file.rgbft img 1 0 in
        Alcotest.(check (list (float 0.))) "values" [ Precision.f32 (44. /. 255.); 1. ] [ g0; g1 ];
        refused "size past the file" (fun () -> Netpbm_file.read_netpbm ~colour:true options "P6\n64 64\n255\n\000\000\000");
        refused "size that wraps" (fun () -> Netpbm_file.read_netpbm ~colour:true options "P6\n2305843009213693952 4\n255\n\000"));
  ]

let nested_font = Hostile_files.nested_font

let font_tests =
  [
    Alcotest.test_case "TrueType: composite glyphs nested 8 deep are bounded" `Quick (fun () ->
        (* 2⁸ glyphs: read; 12⁸ (430 million): refused at once instead of running for hours *)
        let layout k =
          match Font.parse (nested_font k) with
          | Error m -> Alcotest.failf "the font: %s" m
          | Ok f -> Font.layout f [| Char.code 'A' |] ~offset:(Vec.make 0. 0. 0.)
        in
        (match layout 2 with Ok [ _ ] -> () | Ok _ -> Alcotest.fail "one glyph" | Error m -> Alcotest.failf "2⁸ glyphs: %s" m);
        let t0 = Unix.gettimeofday () in
        (match layout 12 with
        | Ok _ -> Alcotest.fail "12⁸ glyphs laid out"
        | Error m -> Alcotest.(check string) "message" "a composite glyph is made of more than 10000 glyphs" m);
        Alcotest.(check bool) "at once" true (Unix.gettimeofday () -. t0 < 2.));
  ]

let tests = tests @ font_tests
