(* Render statistics: the counters one worker keeps, and their sum over workers. *)

type t = {
  mutable camera_rays : int;
  mutable reflected_rays : int;
  mutable refracted_rays : int;
  mutable shadow_rays : int;
  mutable sphere_tests : int;
  mutable sphere_hits : int;
  mutable plane_tests : int;
  mutable plane_hits : int;
  mutable triangle_tests : int;
  mutable triangle_hits : int;
  mutable mesh_tests : int;
  mutable mesh_hits : int;
  mutable box_tests : int;
  mutable box_hits : int;
  mutable cone_tests : int;
  mutable cone_hits : int;
  mutable disc_tests : int;
  mutable disc_hits : int;
  mutable torus_tests : int;
  mutable torus_hits : int;
  mutable torus_bound_hits : int;
  mutable roots_tested : int;
  mutable roots_eliminated : int;
  mutable max_level : int;
  mutable samples : int;
  mutable csg_union_tests : int;
  mutable csg_union_hits : int;
  mutable csg_intersection_tests : int;
  mutable csg_intersection_hits : int;
  mutable csg_merge_tests : int;
  mutable csg_merge_hits : int;
  mutable ttf_tests : int;
  mutable ttf_hits : int;
  mutable polygon_tests : int;
  mutable polygon_hits : int;
  mutable quadric_tests : int;
  mutable quadric_hits : int;
  mutable bound_tests : int;
  mutable bound_hits : int;
  mutable blob_tests : int;
  mutable blob_hits : int;
  mutable blob_element_tests : int;
  mutable blob_element_hits : int;
  mutable blob_bound_tests : int;
  mutable blob_bound_hits : int;
  mutable hfield_tests : int;
  mutable hfield_hits : int;
  mutable hfield_box_hits : int;
  mutable hfield_triangle_tests : int;
  mutable hfield_triangle_hits : int;
  mutable hfield_block_tests : int;
  mutable hfield_block_hits : int;
  mutable hfield_cell_tests : int;
  mutable hfield_cell_hits : int;
  mutable superellipsoid_tests : int;
  mutable superellipsoid_hits : int;
  mutable ovus_tests : int;
  mutable ovus_hits : int;
  mutable sphere_sweep_tests : int;
  mutable sphere_sweep_hits : int;
  mutable prism_tests : int;
  mutable prism_hits : int;
  mutable prism_bound_tests : int;
  mutable prism_bound_hits : int;
  mutable lathe_tests : int;
  mutable lathe_hits : int;
  mutable lathe_bound_tests : int;
  mutable lathe_bound_hits : int;
  mutable sor_tests : int;
  mutable sor_hits : int;
  mutable sor_bound_tests : int;
  mutable sor_bound_hits : int;
  mutable fractal_tests : int;
  mutable fractal_hits : int;
  mutable bicubic_tests : int;
  mutable bicubic_hits : int;
  mutable poly_tests : int;
  mutable poly_hits : int;
  mutable parametric_tests : int;
  mutable parametric_hits : int;
  mutable parametric_bound_tests : int;
  mutable parametric_bound_hits : int;
  mutable parametric_cut : int;
  mutable iso_tests : int;
  mutable iso_hits : int;
  mutable iso_bound_tests : int;
  mutable iso_bound_hits : int;
  mutable iso_cache_tests : int;
  mutable iso_cache_hits : int;
  mutable iso_roots : int;
  mutable iso_found : float array;
}

let iso_width = 5

let create () =
  {
    camera_rays = 0; reflected_rays = 0; refracted_rays = 0; shadow_rays = 0; sphere_tests = 0;
    sphere_hits = 0; plane_tests = 0; plane_hits = 0; triangle_tests = 0; triangle_hits = 0; mesh_tests = 0; mesh_hits = 0; box_tests = 0; box_hits = 0; cone_tests = 0; cone_hits = 0; disc_tests = 0; disc_hits = 0;
    torus_tests = 0; torus_hits = 0; torus_bound_hits = 0; roots_tested = 0; roots_eliminated = 0; max_level = 0; samples = 0;
    csg_union_tests = 0; csg_union_hits = 0; csg_intersection_tests = 0; csg_intersection_hits = 0; csg_merge_tests = 0;
    csg_merge_hits = 0; ttf_tests = 0; ttf_hits = 0;
    polygon_tests = 0; polygon_hits = 0; quadric_tests = 0; quadric_hits = 0;
    bound_tests = 0; bound_hits = 0;
    blob_tests = 0; blob_hits = 0; blob_element_tests = 0; blob_element_hits = 0; blob_bound_tests = 0; blob_bound_hits = 0;
    hfield_tests = 0; hfield_hits = 0; hfield_box_hits = 0;
    hfield_triangle_tests = 0; hfield_triangle_hits = 0; hfield_block_tests = 0; hfield_block_hits = 0; hfield_cell_tests = 0;
    hfield_cell_hits = 0;
    superellipsoid_tests = 0; superellipsoid_hits = 0; ovus_tests = 0; ovus_hits = 0; sphere_sweep_tests = 0; sphere_sweep_hits = 0;
    prism_tests = 0; prism_hits = 0; prism_bound_tests = 0; prism_bound_hits = 0; lathe_tests = 0; lathe_hits = 0; lathe_bound_tests = 0; lathe_bound_hits = 0; sor_tests = 0; sor_hits = 0; sor_bound_tests = 0; sor_bound_hits = 0;
    fractal_tests = 0; fractal_hits = 0; bicubic_tests = 0; bicubic_hits = 0;
    poly_tests = 0; poly_hits = 0;
    parametric_tests = 0; parametric_hits = 0; parametric_bound_tests = 0; parametric_bound_hits = 0; parametric_cut = 0;
    iso_tests = 0; iso_hits = 0; iso_bound_tests = 0; iso_bound_hits = 0; iso_cache_tests = 0; iso_cache_hits = 0; iso_roots = 0;
    iso_found = [||];
  }

(* the room of isosurface [key], the array grown (with zeros) when it is too short *)
let iso_slot s key =
  let need = (key + 1) * iso_width in
  if Array.length s.iso_found < need then begin
    let a = Array.make (max need (2 * Array.length s.iso_found)) 0. in
    Array.blit s.iso_found 0 a 0 (Array.length s.iso_found);
    s.iso_found <- a
  end;
  key * iso_width

(* the per-isosurface values of two workers: largest gradients and variation, summed counts *)
let merge_found a b =
  let n = max (Array.length a) (Array.length b) in
  let get x i = if i < Array.length x then x.(i) else 0. in
  Array.init n (fun i ->
      let x = get a i and y = get b i in
      match i mod iso_width with 2 | 3 -> x +. y | _ -> if x < y then y else x)

let merge a b =
  {
    camera_rays = a.camera_rays + b.camera_rays;
    reflected_rays = a.reflected_rays + b.reflected_rays;
    refracted_rays = a.refracted_rays + b.refracted_rays;
    shadow_rays = a.shadow_rays + b.shadow_rays;
    sphere_tests = a.sphere_tests + b.sphere_tests;
    sphere_hits = a.sphere_hits + b.sphere_hits;
    plane_tests = a.plane_tests + b.plane_tests;
    plane_hits = a.plane_hits + b.plane_hits;
    triangle_tests = a.triangle_tests + b.triangle_tests;
    triangle_hits = a.triangle_hits + b.triangle_hits;
    mesh_tests = a.mesh_tests + b.mesh_tests;
    mesh_hits = a.mesh_hits + b.mesh_hits;
    box_tests = a.box_tests + b.box_tests;
    box_hits = a.box_hits + b.box_hits;
    cone_tests = a.cone_tests + b.cone_tests;
    cone_hits = a.cone_hits + b.cone_hits;
    disc_tests = a.disc_tests + b.disc_tests;
    disc_hits = a.disc_hits + b.disc_hits;
    torus_tests = a.torus_tests + b.torus_tests;
    torus_hits = a.torus_hits + b.torus_hits;
    torus_bound_hits = a.torus_bound_hits + b.torus_bound_hits;
    roots_tested = a.roots_tested + b.roots_tested;
    roots_eliminated = a.roots_eliminated + b.roots_eliminated;
    max_level = max a.max_level b.max_level;
    samples = a.samples + b.samples;
    csg_union_tests = a.csg_union_tests + b.csg_union_tests;
    csg_union_hits = a.csg_union_hits + b.csg_union_hits;
    csg_intersection_tests = a.csg_intersection_tests + b.csg_intersection_tests;
    csg_intersection_hits = a.csg_intersection_hits + b.csg_intersection_hits;
    csg_merge_tests = a.csg_merge_tests + b.csg_merge_tests;
    ttf_tests = a.ttf_tests + b.ttf_tests;
    ttf_hits = a.ttf_hits + b.ttf_hits;
    csg_merge_hits = a.csg_merge_hits + b.csg_merge_hits;
    polygon_tests = a.polygon_tests + b.polygon_tests;
    polygon_hits = a.polygon_hits + b.polygon_hits;
    quadric_tests = a.quadric_tests + b.quadric_tests;
    quadric_hits = a.quadric_hits + b.quadric_hits;
    bound_tests = a.bound_tests + b.bound_tests;
    bound_hits = a.bound_hits + b.bound_hits;
    blob_tests = a.blob_tests + b.blob_tests;
    blob_hits = a.blob_hits + b.blob_hits;
    blob_element_tests = a.blob_element_tests + b.blob_element_tests;
    blob_element_hits = a.blob_element_hits + b.blob_element_hits;
    blob_bound_tests = a.blob_bound_tests + b.blob_bound_tests;
    blob_bound_hits = a.blob_bound_hits + b.blob_bound_hits;
    hfield_tests = a.hfield_tests + b.hfield_tests;
    hfield_hits = a.hfield_hits + b.hfield_hits;
    hfield_box_hits = a.hfield_box_hits + b.hfield_box_hits;
    hfield_triangle_tests = a.hfield_triangle_tests + b.hfield_triangle_tests;
    hfield_triangle_hits = a.hfield_triangle_hits + b.hfield_triangle_hits;
    hfield_block_tests = a.hfield_block_tests + b.hfield_block_tests;
    hfield_block_hits = a.hfield_block_hits + b.hfield_block_hits;
    hfield_cell_tests = a.hfield_cell_tests + b.hfield_cell_tests;
    hfield_cell_hits = a.hfield_cell_hits + b.hfield_cell_hits;
    superellipsoid_tests = a.superellipsoid_tests + b.superellipsoid_tests;
    superellipsoid_hits = a.superellipsoid_hits + b.superellipsoid_hits;
    ovus_tests = a.ovus_tests + b.ovus_tests;
    ovus_hits = a.ovus_hits + b.ovus_hits;
    sphere_sweep_tests = a.sphere_sweep_tests + b.sphere_sweep_tests;
    sphere_sweep_hits = a.sphere_sweep_hits + b.sphere_sweep_hits;
    prism_tests = a.prism_tests + b.prism_tests;
    prism_hits = a.prism_hits + b.prism_hits;
    prism_bound_tests = a.prism_bound_tests + b.prism_bound_tests;
    prism_bound_hits = a.prism_bound_hits + b.prism_bound_hits;
    lathe_tests = a.lathe_tests + b.lathe_tests;
    lathe_hits = a.lathe_hits + b.lathe_hits;
    lathe_bound_tests = a.lathe_bound_tests + b.lathe_bound_tests;
    lathe_bound_hits = a.lathe_bound_hits + b.lathe_bound_hits;
    sor_tests = a.sor_tests + b.sor_tests;
    sor_hits = a.sor_hits + b.sor_hits;
    sor_bound_tests = a.sor_bound_tests + b.sor_bound_tests;
    sor_bound_hits = a.sor_bound_hits + b.sor_bound_hits;
    fractal_tests = a.fractal_tests + b.fractal_tests;
    fractal_hits = a.fractal_hits + b.fractal_hits;
    bicubic_tests = a.bicubic_tests + b.bicubic_tests;
    bicubic_hits = a.bicubic_hits + b.bicubic_hits;
    poly_tests = a.poly_tests + b.poly_tests;
    poly_hits = a.poly_hits + b.poly_hits;
    parametric_tests = a.parametric_tests + b.parametric_tests;
    parametric_hits = a.parametric_hits + b.parametric_hits;
    parametric_bound_tests = a.parametric_bound_tests + b.parametric_bound_tests;
    parametric_bound_hits = a.parametric_bound_hits + b.parametric_bound_hits;
    parametric_cut = a.parametric_cut + b.parametric_cut;
    iso_tests = a.iso_tests + b.iso_tests;
    iso_hits = a.iso_hits + b.iso_hits;
    iso_bound_tests = a.iso_bound_tests + b.iso_bound_tests;
    iso_bound_hits = a.iso_bound_hits + b.iso_bound_hits;
    iso_cache_tests = a.iso_cache_tests + b.iso_cache_tests;
    iso_cache_hits = a.iso_cache_hits + b.iso_cache_hits;
    iso_roots = a.iso_roots + b.iso_roots;
    iso_found = merge_found a.iso_found b.iso_found;
  }

type row = { name : string; tests : int; hits : int }
