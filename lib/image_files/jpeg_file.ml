(* JPEG files as POV-Ray 3.7 reads them (jpeg.cpp), through libjpeg (lib/image_files/jpeg_stubs.c). *)
open Image_file

(* status (0 decoded, 1 above the caps, 2 refused), width, height, components, samples or message *)
external decode : string -> int -> int -> int * int * int * int * string = "povml_jpeg_decode"

let read_jpeg (o : options) data =
  (* the samples take a byte each in C, then an OCaml int each *)
  let max_bytes = mul o.max_memory_mb 1048576 / 9 in
  match decode data o.max_pixels max_bytes with
  | 0, width, height, components, samples ->
      check_size o ~format:"JPEG" ~width ~height ~samples:components;
      let curve = assumed_curve o in
      let values = Array.init (String.length samples) (fun i -> Char.code (String.unsafe_get samples i)) in
      let lut = lut_of curve 255 in
      let pixels =
        if components = 1 then Grey { max = 255; grey = values; alpha = None; lut } else Colour { max = 255; rgb = values; alpha = None; lut }
      in
      { width; height; pixels; premultiplied = false }
  | 1, width, height, components, _ ->
      if width = 0 || height = 0 then bad "the JPEG's size %d×%d has no pixels" width height;
      check_size o ~format:"JPEG" ~width ~height ~samples:(max 1 components);
      over_limit "--max-memory MIB" "the JPEG's %d×%d pixels need more memory once decoded than povml's limit of %s MiB" width height
        (commas o.max_memory_mb)
  | _, _, _, _, message -> bad "%s" message
