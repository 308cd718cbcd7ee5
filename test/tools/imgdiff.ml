(* imgdiff A.png B.png: prints the share of identical pixels, the peak channel error and PSNR, and
   writes nothing. A development aid for comparing povml with POV-Ray by hand. *)
let () =
  match Sys.argv with
  | [| _; a; b |] -> (
      match (Povml.Output.read_png a, Povml.Output.read_png b) with
      | Ok ia, Ok ib -> (
          match Povml.Compare.images ia ib with
          | Ok c ->
              Printf.printf "differing %d/%d (%.4f%% identical) peak %d rmse %.4f psnr %.2f\n" c.differing c.pixels
                (100. *. Povml.Compare.identical_share c) c.peak c.rmse (Povml.Compare.psnr c)
          | Error e -> prerr_endline e; exit 1)
      | Error e, _ | _, Error e -> prerr_endline e; exit 1)
  | _ -> prerr_endline "usage: imgdiff A.png B.png"; exit 2
