(* Partial renders put back together. *)

type area = { left : int; top : int; right : int; bottom : int; block : int }

let key = Png_text.area_key
let to_text a = Printf.sprintf "%d %d %d %d %d" a.left a.top a.right a.bottom a.block

let of_text s =
  match List.filter_map int_of_string_opt (String.split_on_char ' ' (String.trim s)) with
  | [ left; top; right; bottom; block ] when left <= right && top <= bottom && left >= 0 && top >= 0 && block > 0 ->
      Some { left; top; right; bottom; block }
  | _ -> None

(* an edge inside the image that is not on a render block's edge *)
let off_block w h a =
  let inner_x x = x > 0 && x < w && x mod a.block <> 0 and inner_y y = y > 0 && y < h && y mod a.block <> 0 in
  inner_x a.left || inner_x (a.right + 1) || inner_y a.top || inner_y (a.bottom + 1)

let fail fmt = Printf.ksprintf (fun m -> Error m) fmt

(* the 8-bit RGB values as stored, read by povml's own decoder *)
let read_png path =
  let raw = { Image_file.gamma_correct = false; default_gamma = None; working_gamma = Gamma_curve.Neutral; gamma_override = false; premultiply = None;
      max_pixels = max_int; max_memory_mb = Scene_limits.default.memory_mb } in
  match Png_file.read_png raw (Png_text.read_all path) with
  | exception Sys_error m -> Error m
  | exception Image_file.Bad m -> Error m
  | exception Image_file.Over_limit { msg; _ } -> Error msg
  | { width; height; pixels = Colour { max = 255; rgb; _ }; _ } ->
      Ok { Encode.width; height; pixels = Bytes.init (3 * width * height) (fun i -> Char.chr rgb.(i)) }
  | _ -> Error "not an 8-bit RGB PNG"

let load path =
  if Sys.file_exists path && Sys.is_directory path then fail "%s: cannot read it: it is a directory, not a PNG file" path
  else
  match read_png path with
  | Error m -> fail "%s: cannot read it: %s" path m
  | Ok img -> (
      match Option.bind (Png_text.find path ~key) of_text with
      | None -> fail "%s: it does not say which part of the image it renders (povml records that in every PNG it writes; POV-Ray's do not)" path
      | Some a when a.right >= img.width || a.bottom >= img.height ->
          fail "%s: its area (%s) lies outside its %dx%d pixels" path (to_text a) img.width img.height
      | Some a -> Ok (path, img, a))

let merge ?(warn = ignore) paths =
  let rec load_all acc = function
    | [] -> Ok (List.rev acc)
    | p :: rest -> ( match load p with Error m -> Error m | Ok x -> load_all (x :: acc) rest)
  in
  match load_all [] paths with
  | Error m -> Error m
  | Ok [] -> fail "no parts to merge"
  | Ok ((p0, (i0 : Encode.t), _) :: _ as parts) -> (
      match List.find_opt (fun (_, (i : Encode.t), _) -> i.width <> i0.width || i.height <> i0.height) parts with
      | Some (p, i, _) -> fail "%s is %dx%d but %s is %dx%d: the parts of one image have its size" p i.width i.height p0 i0.width i0.height
      | None ->
          let w = i0.width and h = i0.height in
          let owner = Array.make (w * h) (-1) in
          let out = Bytes.make (3 * w * h) '\000' in
          let parts = Array.of_list parts in
          let overlap = ref None in
          Array.iteri
            (fun k (_, (img : Encode.t), a) ->
              for y = a.top to a.bottom do
                for x = a.left to a.right do
                  let i = (y * w) + x in
                  if owner.(i) >= 0 && !overlap = None then overlap := Some (owner.(i), k, x, y);
                  owner.(i) <- k;
                  Bytes.blit img.pixels (3 * i) out (3 * i) 3
                done
              done)
            parts;
          let name k = let p, _, _ = parts.(k) in p in
          match !overlap with
          | Some (a, b, x, y) -> fail "%s and %s overlap: both render column %d, row %d" (name a) (name b) (x + 1) (y + 1)
          | None -> (
              let rec gap i = if i >= w * h then None else if owner.(i) < 0 then Some i else gap (i + 1) in
              match gap 0 with
              | Some i -> fail "no part renders column %d, row %d: the parts leave a gap" ((i mod w) + 1) ((i / w) + 1)
              | None ->
                  Array.iter
                    (fun (p, _, a) ->
                      if off_block w h a then
                        warn
                          (Printf.sprintf
                             "%s: its area (columns %d to %d, rows %d to %d) does not begin and end on the edges of %d-pixel render blocks: antialiased pixels along its edges may differ from one render's"
                             p (a.left + 1) (a.right + 1) (a.top + 1) (a.bottom + 1) a.block))
                    parts;
                  Ok { Encode.width = w; height = h; pixels = out }))
