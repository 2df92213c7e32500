// Formal properties of the HAD with its cache, included into had under
// `ifdef FORMAL_HAD (tools/girtd formal; hw/formal.json lists the instances).
// Labelled asserts are the properties; the comment after each is its row.
// Environment, as girtd_backend and its harness treat the HAD: reset first;
// the option and timing registers fixed; one base tick per edge (ticks_i = 1,
// as in hardware); the FIFO's head held until popped; once a flush is asked
// for and the FIFO has drained, no new pixel until the flush is done (the
// harness flushes after the DDA has finished). The VRAM is abstract: it takes
// a request when not busy, runs one operation at a time and ends each with
// one done; the data it returns is free, and so is its time: it may take any
// number of ticks to take a request and to end an operation. The progress
// properties (FORMAL_HAD_LIVENESS) therefore count the HAD's own ticks, those
// in which the VRAM is not busy; with the real VRAM's busy runs
// (vram_busy_run) they give bounds in ticks (hw/README.md).
logic f_past_q = 1'b0;
always_ff @(posedge clk_i) f_past_q <= 1'b1;
logic [girtd_pkg::TIME_W-1:0] f_access_q, f_blend_q;
logic [3:0] f_options_q;
logic [girtd_pkg::FIFO_W-1:0] f_head_q;
logic f_head_held_q, f_draining_q, f_vram_op_q;
always_ff @(posedge clk_i) begin
  {f_access_q, f_blend_q} <= {access_ticks_i, blend_ticks_i};
  f_options_q <= {one_minus_exact_i, write_behind_i, prefetch_i, dirty_bits_i};
  f_head_q <= fifo_data_i;
  f_head_held_q <= rst_ni && !fifo_empty_i && !fifo_pop_o;
  f_draining_q <= rst_ni && (flush_pending_q || flush_i) && (f_draining_q || fifo_empty_i);
  if (!rst_ni) f_vram_op_q <= 1'b0;
  else if (vram_req_o && !vram_busy_i) f_vram_op_q <= 1'b1;
  else if (vram_done_i) f_vram_op_q <= 1'b0;
end
always_comb begin
  if (!f_past_q) assume (!rst_ni);
  assume (ticks_i == girtd_pkg::LONG_TIME_W'(1));
  if (f_past_q) assume ({access_ticks_i, blend_ticks_i} == {f_access_q, f_blend_q} &&
                        {one_minus_exact_i, write_behind_i, prefetch_i, dirty_bits_i} == f_options_q);
  if (f_head_held_q) assume (!fifo_empty_i && fifo_data_i == f_head_q);
  if (f_draining_q) assume (fifo_empty_i);
  // The VRAM: a done only for an operation in flight (which may hand over to the next on its last tick).
  if (vram_done_i) assume (f_vram_op_q);
  if (f_vram_op_q && !vram_done_i) assume (vram_busy_i);
end

`ifdef FORMAL_HAD_LIVENESS
// For had_pops and had_idle only: progress in the HAD's own ticks, those in
// which the VRAM is not busy (with an operation of the HAD's or other work),
// so that the VRAM may take any time. With the real VRAM, busy at most
// 2 max(cycle, 1) ticks in a row (vram_busy_run), a bound of N own ticks is
// one of N (2 max(cycle, 1) + 1) ticks (hw/README.md).
localparam int F_OWN_MAX = 2 * (2 * ((1 << girtd_pkg::TIME_W) - 1) + 4) + 8;  // had_idle's bound at the largest timing
localparam int F_OWN_W = $clog2(F_OWN_MAX + 2);  // saturates above every bound: no violation hidden
logic [F_OWN_W-1:0] f_unpopped_q, f_quiet_q, f_pixel_own;
function automatic logic [F_OWN_W-1:0] f_count(input logic [F_OWN_W-1:0] n);  // own ticks, saturating
  f_count = n + F_OWN_W'(!vram_busy_i && n != '1);
endfunction
always_ff @(posedge clk_i) begin
  // a pixel waiting in the FIFO: own ticks since the last pop; the input stopped: own ticks since
  f_unpopped_q <= !rst_ni || fifo_empty_i || fifo_pop_o ? '0 : f_count(f_unpopped_q);
  f_quiet_q <= !rst_ni || !fifo_empty_i || flush_i ? '0 : f_count(f_quiet_q);
end
assign f_pixel_own = F_OWN_W'(f_access_q) + F_OWN_W'(f_blend_q) + F_OWN_W'(4);  // an access, a blend, hand-overs
`endif

// One pixel, chosen by the solver, followed: the value the HAD last wrote to
// its cell, and where that value is while it is not yet in the VRAM (only in
// the cache, or in the write-behind register).
(* anyconst *) logic [NW-1:0] f_page;
(* anyconst *) logic [IW-1:0] f_index;
function automatic logic [CW-1:0] f_cell_of(input logic [PW-1:0] data);  // constant part selects
  f_cell_of = '0;
  for (int i = 0; i < girtd_pkg::PAGE_PIXELS; i++) if (f_index == IW'(i)) f_cell_of = data[i*CW+:CW];
endfunction
function automatic logic [girtd_pkg::CACHE_SLOT_W-1:0] f_slot_of(input logic [NW-1:0] page);
  f_slot_of = girtd_pkg::CACHE_SLOT_W'(32'(page) % PAGES);
endfunction
logic [CW-1:0] f_value_q;
logic f_in_cache_only_q, f_in_write_behind_q, f_flushed;
logic f_vram_write, f_capture, f_mine;
assign f_vram_write = vram_req_o && vram_we_o && !vram_busy_i && vram_page_o == f_page;
assign f_capture = state_q == H_IDLE && miss_go && must_write_back && write_behind_i && victim_page == f_page;
assign f_mine = cache_write && pix_page == f_page && x == f_index;
always_ff @(posedge clk_i) begin
  if (!rst_ni) {f_in_cache_only_q, f_in_write_behind_q} <= '0;
  else begin
    if (f_mine) f_value_q <= cell_new;
    if (f_mine) f_in_cache_only_q <= 1'b1;
    else if (f_vram_write || f_capture) f_in_cache_only_q <= 1'b0;
    if (f_capture && f_in_cache_only_q) f_in_write_behind_q <= 1'b1;
    else if (f_vram_write) f_in_write_behind_q <= 1'b0;
  end
end
// The frame-end flush has just ended: the flush pending a tick ago is no more.
logic f_flush_pending_q;
always_ff @(posedge clk_i) f_flush_pending_q <= rst_ni && flush_pending_q;
assign f_flushed = f_flush_pending_q && !flush_pending_q && !flush_i;

always_comb if (f_past_q && rst_ni) begin
  if (f_vram_write && (f_in_cache_only_q || f_in_write_behind_q))
    had_write_back_data: assert (f_cell_of(vram_wdata_o) == f_value_q);  // a page written back carries the last value written to each pixel
  if (f_capture && f_in_cache_only_q)
    had_write_behind_data: assert (f_cell_of(victim_data) == f_value_q);  // the write-behind register takes the page as last written
  if (cache_load && f_slot_of(pix_page) == f_slot_of(f_page))
    had_no_lost_write: assert (!f_in_cache_only_q);  // a page with a written pixel is written back (or taken by write-behind) before its slot is reloaded
  if (f_flushed)
    had_flush_complete: assert (!f_in_cache_only_q && !f_in_write_behind_q);  // after the frame-end flush every written pixel is on its way to the VRAM
  if (f_flushed)
    had_flush_forgets: assert (!head_hit && !pf_valid_q && !pf_loading_q);  // after the flush no page of the frame is kept, cached or prefetched (any head pixel misses)
  had_pop_not_empty: assert (!fifo_pop_o || !fifo_empty_i);  // never pops an empty FIFO
  had_load_or_write: assert (!(cache_load && cache_write));  // never loads a page and writes a pixel in the same tick (the cache's contract)
`ifdef FORMAL_HAD_LIVENESS
  had_pops: assert (f_unpopped_q < 2 * f_pixel_own);  // a pixel in the FIFO: one is popped within 2 (access + blend + 4) own ticks (ticks the VRAM is not busy; any VRAM)
  if (f_quiet_q >= 2 * f_pixel_own + F_OWN_W'(8) && !flush_i)
    had_idle: assert (idle_o);  // input stopped: idle (flush done, write-behind and prefetch drained) within 2 (access + blend + 4) + 8 own ticks (any VRAM)
`endif
  if (f_in_write_behind_q)
    had_write_behind_held: assert (wb_pending_q && wb_page_q == f_page && f_cell_of(wb_data_q) == f_value_q);  // the write-behind register holds its page until it is written
end
