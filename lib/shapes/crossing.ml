(* A crossing's report: what a shape found there besides its depth. *)

type t = {
  mutable px : float;
  mutable py : float;
  mutable pz : float;
  mutable nx : float;
  mutable ny : float;
  mutable nz : float;
  mutable u : float;
  mutable v : float;
}

let width = 8
let create () = { px = 0.; py = 0.; pz = 0.; nx = 0.; ny = 0.; nz = 0.; u = 0.; v = 0. }
let none = create ()

let set c (p : Vec.t) (n : Vec.t) u v =
  c.px <- p.x;
  c.py <- p.y;
  c.pz <- p.z;
  c.nx <- n.x;
  c.ny <- n.y;
  c.nz <- n.z;
  c.u <- u;
  c.v <- v

let blit s c =
  c.px <- s.px;
  c.py <- s.py;
  c.pz <- s.pz;
  c.nx <- s.nx;
  c.ny <- s.ny;
  c.nz <- s.nz;
  c.u <- s.u;
  c.v <- s.v

let copy c = { px = c.px; py = c.py; pz = c.pz; nx = c.nx; ny = c.ny; nz = c.nz; u = c.u; v = c.v }

let store c a k =
  a.(k) <- c.px;
  a.(k + 1) <- c.py;
  a.(k + 2) <- c.pz;
  a.(k + 3) <- c.nx;
  a.(k + 4) <- c.ny;
  a.(k + 5) <- c.nz;
  a.(k + 6) <- c.u;
  a.(k + 7) <- c.v

let load a k c =
  c.px <- a.(k);
  c.py <- a.(k + 1);
  c.pz <- a.(k + 2);
  c.nx <- a.(k + 3);
  c.ny <- a.(k + 4);
  c.nz <- a.(k + 5);
  c.u <- a.(k + 6);
  c.v <- a.(k + 7)

let point c = Vec.make c.px c.py c.pz
let[@inline] point_x c = c.px
let[@inline] point_y c = c.py
let[@inline] point_z c = c.pz
let normal c = Vec.make c.nx c.ny c.nz
let[@inline] u c = c.u
let[@inline] v c = c.v
let uv c = Vec.make c.u c.v 0.
