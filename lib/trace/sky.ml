(* The sky and the background (§8.4, §18.1). *)

open Compiled

let colour sc (d : Vec.t) : Traced.t =
  let bg = sc.background in
  match sc.sky with
  | None -> if sc.legacy then { r = bg.red; g = bg.green; b = bg.blue; tr = bg.transmit } else { r = bg.red; g = bg.green; b = bg.blue; tr = 0. }
  | Some sky ->
      let p = match sky.sky_trans with None -> d | Some t -> Transform.inv_point t d in
      let pigs = List.rev_map (fun pg -> Pigment.colour_at sc.noise_generator pg Patterns.no_hit p) sky.sky_pigments in
      let e = sky.sky_emission in
      if not sc.legacy then
        let col, fil =
          List.fold_left
            (fun ((col : Rgb.t), (fil : Rgb.t)) (c : Colour.t) ->
              let k = 1. -. c.filter -. c.transmit in
              ( Rgb.add col (Rgb.mul (Rgb.scale k (Rgb.mul (Colour.rgb c) fil)) e),
                Rgb.mul fil (Colour.transmitted c) ))
            (Rgb.black, Rgb.white) pigs
        in
        let col = Rgb.add col (Rgb.mul (Colour.rgb bg) fil) in
        { r = col.r; g = col.g; b = col.b; tr = 0. }
      else
        let col, f, _ =
          List.fold_left
            (fun ((col : Rgb.t), (f : Colour.t), tr) (c : Colour.t) ->
              let col = Rgb.add col (Rgb.scale (tr *. (1. -. c.filter -. c.transmit)) (Colour.rgb c)) in
              let f =
                { Colour.red = f.red *. c.red; green = f.green *. c.green; blue = f.blue *. c.blue; filter = f.filter *. c.filter; transmit = f.transmit *. c.transmit }
              in
              (col, f, Float.abs f.filter +. Float.abs f.transmit))
            (Rgb.black, { Colour.red = 1.; green = 1.; blue = 1.; filter = 1.; transmit = 1. }, 1.)
            pigs
        in
        let col = Rgb.add (Rgb.mul col e) (Rgb.mul (Colour.rgb bg) (Colour.transmitted f)) in
        { r = col.r; g = col.g; b = col.b; tr = 0. }
