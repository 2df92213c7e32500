// Formal properties of pixel_cache, included into it under `ifdef FORMAL_PIXEL_CACHE
// (tools/girtd formal; hw/formal.json lists the instances proven). Labelled
// asserts are the properties; the comment after each is its table row.
// The environment is the HAD's use of it: reset first; a load and a pixel
// write never in the same tick (H_FETCH and H_ACCESS/H_BLEND); a pixel is
// written only while its page is in the cache (the HAD fetched it first). The
// HAD's proof asserts the first (had_load_or_write); the second is this
// proof's assumption only (the cache has no port that says it).
logic f_past_q = 1'b0;
always_ff @(posedge clk_i) f_past_q <= 1'b1;
always_comb begin
  if (!f_past_q) assume (!rst_ni);
  if (rst_ni) assume (!(load_i && write_i));
  if (rst_ni && write_i) assume (valid_q[pix_slot] && page_q[pix_slot] == pix_page_i);
end

// One pixel of the screen, chosen by the solver (any page, any place in it),
// followed apart from the cache: is its page in, what its cell holds, whether
// its page was written since it came in.
(* anyconst *) logic [NW-1:0] f_page;
(* anyconst *) logic [IW-1:0] f_index;
// The cell at the chosen place of a page's data (constant part selects: a
// multiplied index is slow for the solver).
function automatic logic [CW-1:0] f_cell_of(input logic [PW-1:0] data);
  f_cell_of = '0;
  for (int i = 0; i < PIXELS; i++) if (f_index == IW'(i)) f_cell_of = data[i*CW+:CW];
endfunction
logic [SW-1:0] f_slot;
assign f_slot = slot_of(f_page);
logic f_in_q, f_dirty_q;
logic [CW-1:0] f_cell_q;
always_ff @(posedge clk_i) begin
  if (!rst_ni || (invalidate_i && flush_slot == f_slot)) f_in_q <= 1'b0;
  else if (load_i && load_slot == f_slot) f_in_q <= load_page_i == f_page;
  if (load_i && load_page_i == f_page) begin
    f_cell_q <= f_cell_of(load_data_i);
    f_dirty_q <= 1'b0;
  end else if (write_i && pix_page_i == f_page) begin
    if (pix_index_i == f_index) f_cell_q <= write_data_i;
    f_dirty_q <= 1'b1;
  end
end

always_comb if (f_past_q && rst_ni) begin
  if (head_page_i == f_page) begin
    cache_hit: assert (head_hit_o == f_in_q);  // a page hits exactly while it is in (loaded, not since displaced or invalidated)
    if (f_in_q) cache_head_data: assert (f_cell_of(head_slot_data_o) == f_cell_q);  // a pixel written lands in the page its address names: the page reads it back
    if (f_in_q) cache_dirty: assert (head_slot_dirty_o == f_dirty_q);  // a page is dirty exactly when a pixel of it was written since it came in
  end
  if (f_in_q && pix_page_i == f_page && pix_index_i == f_index)
    cache_pixel: assert (pix_cell_o == f_cell_q);  // the pixel in hand reads its own cell
  if (f_in_q && flush_slot == f_slot)
    cache_flush: assert (flush_valid_o && flush_page_o == f_page && flush_dirty_o == f_dirty_q &&
                         f_cell_of(flush_data_o) == f_cell_q);  // the frame-end flush sees the page, its dirty bit and its data
  cache_slot: assert (f_in_q == (valid_q[f_slot] && page_q[f_slot] == f_page));  // a page is in its slot exactly when the cache says so
  if (f_in_q) cache_stored: assert (cell_q[f_slot][f_index] == f_cell_q && dirty_q[f_slot] == f_dirty_q);  // what the slot holds
end
