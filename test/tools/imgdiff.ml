(* imgdiff A.png B.png: prints the share of identical pixels, the peak channel error and PSNR, and
   writes nothing. A development aid for comparing povml with POV-Ray by hand. *)
let () =
  match Sys.argv with
  | [| _; a; b |] -> (
      match (Output.read_png a, Output.read_png b) with
      | Ok ia, Ok ib -> (
          match Compare.images ia ib with
          | Ok c ->
              Printf.printf "differing %d/%d (%.4f%% identical) peak %d rmse %.4f psnr %.2f\n" c.differing c.pixels
                (100. *. Compare.identical_share c) c.peak c.rmse (Compare.psnr c)
          | Error e -> prerr_endline e; exit 1)
      | Error e, _ | _, Error e -> prerr_endline e; exit 1)
  | [| _; _; _; "-v" |] -> ()
  | _ -> prerr_endline "usage: imgdiff A.png B.png [-v]"; exit 2

(* With a third argument, list the differing pixels. *)
let () =
  match Sys.argv with
  | [| _; a; b; "-v" |] -> (
      match (Output.read_png a, Output.read_png b) with
      | Ok ia, Ok ib ->
          for p = 0 to (ia.width * ia.height) - 1 do
            let g i = Char.code (Bytes.get ia.pixels i) and h i = Char.code (Bytes.get ib.pixels i) in
            if g (3 * p) <> h (3 * p) || g ((3 * p) + 1) <> h ((3 * p) + 1) || g ((3 * p) + 2) <> h ((3 * p) + 2) then
              Printf.printf "(%d,%d): %d %d %d vs %d %d %d\n" (p mod ia.width) (p / ia.width) (g (3 * p)) (g ((3 * p) + 1)) (g ((3 * p) + 2)) (h (3 * p)) (h ((3 * p) + 1)) (h ((3 * p) + 2))
          done
      | _ -> ())
  | _ -> ()
