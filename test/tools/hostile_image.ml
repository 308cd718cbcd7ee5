(* hostile_image KIND OUT: writes a malformed or hostile image file of the kind named to OUT, for
   the tests of the decoders (test/cram/hostile_images.t). The large ones are made here, at test
   time, rather than committed. *)

open Hostile_files

let make = function
  | "gif-code-size-13" -> gif ~code_size:13 4 4 []
  | "gif-code-size-1" -> gif ~code_size:1 4 4 []
  | "gif-index-beyond-table" -> gif ~code_size:8 16 16 (List.init 256 Fun.id)
  | "gif-0x0" -> gif 0 0 []
  | "gif-extra-pixels" -> gif 2 2 [ 0; 1; 0; 1; 1 ]
  | "gif-65535x65535" -> gif 65535 65535 [ 0 ]
  | "ppm-overflow" -> "P6\n2305843009213693952 4\n255\n" ^ String.make 64 '\000'
  | "ppm-huge" -> "P6\n100000 100000\n255\n" ^ String.make 64 '\000'
  | "ppm-short" -> "P6\n64 64\n255\n" ^ String.make 64 '\000'
  | "ppm-ascii-short" -> "P3\n4000 4000\n255\n1 2 3\n"
  | "ppm-ascii-long-number" -> "P3\n1 1\n255\n99999999999999999999999999999999999999 300 7\n"
  | "pgm-negative" -> "P5\n-1 -1\n255\n"
  | "png-bomb" ->
      (* 1×1 RGB: 4 bytes promised; 1 GiB and more inflated *)
      png [ ihdr 1 1; chunk "IDAT" (bomb 5_000_000) ]
  | "png-bad-crc" -> png [ ihdr 1 1; chunk ~bad_crc:true "IDAT" (stored "\000\255\000\000") ]
  | "png-bit-depth-3" -> png [ ihdr ~depth:3 1 1; chunk "IDAT" (stored "\000\255\000\000") ]
  | "png-rgb-depth-4" -> png [ ihdr ~depth:4 1 1; chunk "IDAT" (stored "\000\255\000\000") ]
  | "png-100000x100000" -> png [ ihdr 100_000 100_000; chunk "IDAT" (bomb 1000) ]
  | "png-8000x8000-tiny" -> png [ ihdr 8000 8000; chunk "IDAT" (stored (String.make 100 '\000')) ]
  | "png-2000000x1" -> png [ ihdr 2_000_000 1; chunk "IDAT" (stored "\000") ]
  | "png-no-plte" -> png [ ihdr ~ctype:3 1 1; chunk "IDAT" (stored "\000\000") ]
  | "tga-65535x65535" -> tga ~rle:false 65535 65535 (String.make 64 '\000')
  | "tga-rle-short" -> tga ~rle:true 2048 2048 "\255\000\000\255"
  | "jpeg-truncated" -> let s = jpeg () in String.sub s 0 (String.length s - 40)
  | "jpeg-65500x65500" ->
      (* the SOF0 of a real file with its size made huge *)
      let s = Bytes.of_string (jpeg ()) in
      let rec sof i = if Bytes.get s i = '\xff' && Bytes.get s (i + 1) = '\xc0' then i else sof (i + 1) in
      let i = sof 2 in
      Bytes.blit_string "\xff\xdc\xff\xdc" 0 s (i + 5) 4;
      Bytes.to_string s
  | "jpeg-bogus-huffman" ->
      (* a Huffman table whose code counts add up to more than 256: camlimages' binding jumped
         back into a C frame that had returned (a segmentation fault) *)
      let s = Bytes.of_string (jpeg ()) in
      let rec dht i = if Bytes.get s i = '\xff' && Bytes.get s (i + 1) = '\xc4' then i else dht (i + 1) in
      let i = dht 2 in
      Bytes.fill s (i + 5) 16 '\xff';
      Bytes.to_string s
  | "ttf-nested-composites" -> nested_font 12
  | k -> failwith ("unknown kind " ^ k)

let () =
  match Sys.argv with
  | [| _; kind; out |] ->
      let oc = open_out_bin out in
      output_string oc (make kind);
      close_out oc
  | _ ->
      prerr_endline "usage: hostile_image KIND OUT";
      exit 2
