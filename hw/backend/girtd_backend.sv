// GIRTD's back end as one RTL top (§4-§7): DDA -> FIFO -> HAD (+ cache) ->
// VRAM. Everything runs on one base tick (config timing.base_tick_ns, 5 ns);
// the DDA acts on every `dda_period_ticks_i`-th tick (35 ns = 7) it is not
// stalled on, on a clock of its own gated from it (dda_clk_i), the HAD
// counts its access and blend times and the VRAM its cycles in ticks, all
// run-time inputs. The harness loads parameter sets and drives the frame:
// clear (serial port), triangles, flush (cache page back to VRAM), swap.
module girtd_backend (
    input  logic clk_i,
    input  logic rst_ni,
    // The DDA's clock: clk_i gated by dda_step_o, which the harness reads
    // with clk_i low and raises together with clk_i (simulation: a Verilated
    // model then evaluates the DDA only on the ticks it acts on; every DDA
    // register holds on the others, so this is the clock enable it was).
    input  logic dda_clk_i,
    output logic dda_step_o,
    // Timing and options (run-time)
    input  logic [girtd_pkg::DDA_PERIOD_W-1:0] dda_period_ticks_i,
    input  logic [girtd_pkg::TIME_W-1:0]       had_access_ticks_i,
    input  logic [girtd_pkg::TIME_W-1:0]       had_blend_ticks_i,
    input  logic [girtd_pkg::TIME_W-1:0]       vram_cycle_ticks_i,
    input  logic [girtd_pkg::LONG_TIME_W-1:0]  clear_ticks_i,
    input  logic [girtd_pkg::LONG_TIME_W-1:0]  vram_steal_period_ticks_i,
    input  logic [girtd_pkg::FIFO_COUNT_W-1:0] fifo_limit_i,
    input  logic        write_behind_i,
    input  logic        prefetch_i,
    input  logic        dirty_bits_i,
    input  logic        one_minus_exact_i,
    input  logic        walk_fix_i,
    input  logic        pipelined_compare_i,
    // Parameter set of one triangle (as the dda top)
    input  logic                                 in_valid_i,
    output logic                                 in_ready_o,
    input  logic [girtd_pkg::XY_W-1:0]           x0_i, y0_i, xmin_i, xmax_i, ymax_i,
    input  logic                                 q_zero_i,
    input  logic signed [girtd_pkg::Q_K_W-1:0]   q_k_i,
    input  logic [2:0]                           hard_edges_i,
    input  logic                                 clamped_i,
    input  logic signed [girtd_pkg::COLOR_W-1:0] r_i, r_dx_i, r_dy_i, g_i, g_dx_i, g_dy_i, b_i, b_dx_i, b_dy_i,
    input  logic signed [girtd_pkg::T_W-1:0]     t_i, t_dx_i, t_dy_i,
    input  logic signed [girtd_pkg::Z_W-1:0]     z_i, z_dx_i, z_dy_i,
    input  logic signed [girtd_pkg::D_W-1:0]     d1_i, d1_dx_i, d1_dy_i, d2_i, d2_dx_i, d2_dy_i,
    input  logic signed [girtd_pkg::D_W-1:0]     d3_i, d3_dx_i, d3_dy_i,
    // Frame control
    input  logic        clear_i,
    input  logic [3*girtd_pkg::COLOR_OUT-1:0] background_i,
    input  logic        flush_i,
    input  logic        swap_i,
    output logic        idle_o,  // DDA idle, FIFO empty, HAD idle, VRAM free
    output logic        front_o,
    // Probes: the DDA's state (models/dda state numbering) and whether this
    // tick is a DDA clock spent on a triangle.
    output logic [girtd_pkg::DDA_STATE_W-1:0] dda_state_o,
    output logic        dda_active_o,
    // ... and the pixel the DDA pushes into the FIFO on this tick, if any.
    output logic        pixel_push_o,
    output logic [girtd_pkg::SCREEN_BITS-1:0] pixel_x_o, pixel_y_o,
    // Simulation: the tick warp. This edge stands for ticks_i base ticks (tie
    // to 1 in hardware); more than one only when quiet_o, the ticks from this
    // one on in which no unit decides anything (only timers and counters
    // run), is at least that many: the harness skips them in one evaluation.
    input  logic [girtd_pkg::LONG_TIME_W-1:0] ticks_i,
    output logic [girtd_pkg::LONG_TIME_W-1:0] quiet_o,
    // Counters
    output logic [girtd_pkg::TICK_COUNT_W-1:0] dda_clocks_o,     // DDA clocks spent on triangles
    output logic [girtd_pkg::TICK_COUNT_W-1:0] dda_wait_ticks_o, // DDA clocks lost waiting on a full FIFO (in ticks)
    output logic [girtd_pkg::COUNT_W-1:0] pixels_generated_o,
    output logic [girtd_pkg::COUNT_W-1:0] written_o, blended_o, z_rejected_o, dropped_o, page_misses_o,
    output logic [girtd_pkg::TICK_COUNT_W-1:0] had_busy_ticks_o, had_vram_wait_ticks_o,
    output logic [girtd_pkg::FIFO_COUNT_W-1:0] fifo_max_o,
    output logic [girtd_pkg::FIFO_COUNT_W-1:0] fifo_count_o,  // pixels in the DDA -> HAD FIFO now
    output logic [8*girtd_pkg::COUNT_W-1:0] wraps_o,  // the DDA's numerics counters (hw/dda/dda_limits.sv)
    output logic [5*girtd_pkg::COUNT_W-1:0] clips_o,
    output logic [girtd_pkg::COUNT_W-1:0] triangles_affected_o, first_affected_o
);
  localparam int CW = girtd_pkg::FIFO_COUNT_W;

  // Configuration registers: the timing and the options are written while
  // rst_ni is low and held from then on, so no logic hangs on those inputs
  // (a Verilated model evaluates everything fed by a top input on every
  // eval, whether or not it changed).
  logic [girtd_pkg::DDA_PERIOD_W-1:0] dda_period_q;
  logic [girtd_pkg::TIME_W-1:0] had_access_q, had_blend_q, vram_cycle_q;
  logic [girtd_pkg::LONG_TIME_W-1:0] clear_ticks_q, vram_steal_period_q;
  logic [girtd_pkg::FIFO_COUNT_W-1:0] fifo_limit_q;
  logic write_behind_q, prefetch_q, dirty_bits_q, one_minus_exact_q, walk_fix_q, pipelined_compare_q;
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      dda_period_q <= dda_period_ticks_i;
      had_access_q <= had_access_ticks_i;
      had_blend_q <= had_blend_ticks_i;
      vram_cycle_q <= vram_cycle_ticks_i;
      clear_ticks_q <= clear_ticks_i;
      vram_steal_period_q <= vram_steal_period_ticks_i;
      fifo_limit_q <= fifo_limit_i;
      {write_behind_q, prefetch_q, dirty_bits_q} <= {write_behind_i, prefetch_i, dirty_bits_i};
      {one_minus_exact_q, walk_fix_q, pipelined_compare_q} <= {one_minus_exact_i, walk_fix_i, pipelined_compare_i};
    end
  end

  // DDA clock enable: one tick in dda_period_q.
  logic [girtd_pkg::DDA_PERIOD_W-1:0] dda_tick_q;
  logic dda_en;
  assign dda_en = dda_tick_q == '0;
  localparam int LT = girtd_pkg::LONG_TIME_W;
  always_ff @(posedge clk_i) begin
    if (!rst_ni || LT'(dda_tick_q) + ticks_i >= LT'(dda_period_q)) dda_tick_q <= '0;
    else dda_tick_q <= dda_tick_q + girtd_pkg::DDA_PERIOD_W'(ticks_i);
  end

  logic out_valid, fifo_full, fifo_empty, fifo_pop, dda_active, dda_stall, dda_still;
  logic [LT-1:0] dda_quiet, had_quiet, vram_quiet, mem_quiet;
  logic [girtd_pkg::FIFO_X_W-1:0] ox;
  logic [girtd_pkg::FIFO_Y_W-1:0] oy;
  logic [girtd_pkg::FIFO_R_W-1:0] orr;
  logic [girtd_pkg::FIFO_G_W-1:0] og;
  logic [girtd_pkg::FIFO_B_W-1:0] ob;
  logic [girtd_pkg::FIFO_NF_W-1:0] onf;
  logic [girtd_pkg::FIFO_Z_W-1:0] oz;
  logic [girtd_pkg::DDA_STATE_W-1:0] dda_state;
  // The DDA holds (its enable off, or its output stalled on a full FIFO)
  // on every tick but those it is clocked on: inside it, never.
  logic dda_hold, dda_out_stalled, dda_idle_ready, dda_busy, dda_own_still, dda_never_stalled;
  assign dda_out_stalled = out_valid && fifo_full;
  assign dda_hold = !dda_en || dda_out_stalled;
  assign dda_step_o = !rst_ni || !dda_hold;
  assign in_ready_o = dda_idle_ready && !dda_hold;
  assign dda_active = dda_busy && !dda_hold;
  assign dda_stall = dda_en && dda_out_stalled && dda_busy;
  assign dda_still = dda_out_stalled || dda_own_still;
  logic unused_dda_stall;  // inside, the DDA is never held: its own stall output is always 0
  assign unused_dda_stall = dda_never_stalled;
  dda u_dda (
      .clk_i(dda_clk_i), .rst_ni, .en_i(1'b1), .walk_fix_i(walk_fix_q), .pipelined_compare_i(pipelined_compare_q),
      .in_valid_i, .in_ready_o(dda_idle_ready),
      .x0_i, .y0_i, .xmin_i, .xmax_i, .ymax_i, .q_zero_i, .q_k_i, .hard_edges_i, .clamped_i,
      .r_i, .r_dx_i, .r_dy_i, .g_i, .g_dx_i, .g_dy_i, .b_i, .b_dx_i, .b_dy_i, .t_i, .t_dx_i, .t_dy_i,
      .z_i, .z_dx_i, .z_dy_i, .d1_i, .d1_dx_i, .d1_dy_i, .d2_i, .d2_dx_i, .d2_dy_i, .d3_i, .d3_dx_i, .d3_dy_i,
      .out_valid_o(out_valid), .out_ready_i(1'b1), .out_x_o(ox), .out_y_o(oy), .out_r_o(orr),
      .out_g_o(og), .out_b_o(ob), .out_nf_o(onf), .out_z_o(oz), .active_o(dda_busy), .stall_o(dda_never_stalled),
      .state_o(dda_state), .still_o(dda_own_still), .wraps_o, .clips_o, .triangles_affected_o, .first_affected_o);

  logic push;
  logic [girtd_pkg::FIFO_W-1:0] fifo_data;
  logic [CW-1:0] fifo_count;
  assign push = dda_en && out_valid && !fifo_full;
  pixel_fifo #(.W(girtd_pkg::FIFO_W), .DEPTH(girtd_pkg::FIFO_MAX_DEPTH)) u_fifo (
      .clk_i, .rst_ni, .limit_i(fifo_limit_q), .push_i(push), .data_i({ox, oy, orr, og, ob, onf, oz}),
      .full_o(fifo_full), .pop_i(fifo_pop), .data_o(fifo_data), .empty_o(fifo_empty), .count_o(fifo_count));

  logic vram_req, vram_we, vram_busy, vram_done, had_idle;
  logic [girtd_pkg::PAGE_NUMBER_W-1:0] vram_page;
  logic [girtd_pkg::PAGE_PIXELS*girtd_pkg::CELL_W-1:0] vram_wdata, vram_rdata;
  had u_had (
      .clk_i, .rst_ni, .access_ticks_i(had_access_q), .blend_ticks_i(had_blend_q),
      .one_minus_exact_i(one_minus_exact_q), .write_behind_i(write_behind_q), .prefetch_i(prefetch_q),
      .dirty_bits_i(dirty_bits_q), .fifo_empty_i(fifo_empty), .fifo_data_i(fifo_data),
      .fifo_pop_o(fifo_pop), .vram_req_o(vram_req), .vram_we_o(vram_we), .vram_page_o(vram_page),
      .vram_wdata_o(vram_wdata), .vram_rdata_i(vram_rdata), .vram_busy_i(vram_busy), .vram_done_i(vram_done),
      .flush_i, .idle_o(had_idle), .ticks_i, .quiet_o(had_quiet), .written_o, .blended_o, .z_rejected_o, .dropped_o, .page_misses_o,
      .busy_ticks_o(had_busy_ticks_o), .vram_wait_ticks_o(had_vram_wait_ticks_o));

  vram u_vram (
      .clk_i, .rst_ni, .cycle_ticks_i(vram_cycle_q), .clear_ticks_i(clear_ticks_q),
      .steal_period_ticks_i(vram_steal_period_q), .req_i(vram_req), .we_i(vram_we),
      .page_i(vram_page), .wdata_i(vram_wdata), .rdata_o(vram_rdata), .busy_o(vram_busy), .done_o(vram_done),
      .clear_i, .background_i, .swap_i, .front_o, .ticks_i, .quiet_o(vram_quiet));

  logic [LT-1:0] stalled_ticks;
  assign stalled_ticks = ticks_i > LT'(dda_period_q) ? ticks_i : LT'(dda_period_q);
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      dda_clocks_o <= '0;
      dda_wait_ticks_o <= '0;
      pixels_generated_o <= '0;
      fifo_max_o <= '0;
    end else begin
      if (dda_active) dda_clocks_o <= dda_clocks_o + 1'b1;
      // A period per stalled DDA clock; a warp from a stalled clock spans
      // whole periods (quiet_o), each a stalled clock.
      if (dda_stall)
        dda_wait_ticks_o <= dda_wait_ticks_o + girtd_pkg::TICK_COUNT_W'(stalled_ticks);
      if (push) pixels_generated_o <= pixels_generated_o + 1'b1;
      if (fifo_count > fifo_max_o) fifo_max_o <= fifo_count;
    end
  end

  // The tick warp's bound. Between enabled ticks the DDA is quiet until the
  // next one. On an enabled tick, still (stalled, or idle and empty), it
  // stays so for as long as the memory side decides nothing (only a pop ends
  // a stall): then whole periods, each enabled tick of which only counts
  // the wait, or less than one.
  logic [LT-1:0] still_quiet;
  assign mem_quiet = had_quiet < vram_quiet ? had_quiet : vram_quiet;
  assign still_quiet = mem_quiet < LT'(dda_period_q) ? mem_quiet : mem_quiet - mem_quiet % LT'(dda_period_q);
  assign dda_quiet = !dda_en ? LT'(dda_period_q) - LT'(dda_tick_q) : dda_still ? still_quiet : '0;
  assign quiet_o = dda_quiet < mem_quiet ? dda_quiet : mem_quiet;

`ifndef SYNTHESIS
  // A driver that warps over a tick something happens on breaks exactness.
  always_ff @(posedge clk_i)
    if (rst_ni && ticks_i > 1 && ticks_i > quiet_o) $error("girtd_backend: ticks_i %0d over quiet_o %0d", ticks_i, quiet_o);
`endif

  assign idle_o = in_ready_o && !out_valid && dda_state == girtd_pkg::S_IDLE && fifo_empty && had_idle && !vram_busy;
  assign dda_state_o = dda_state;
  assign dda_active_o = dda_active;
  assign pixel_push_o = push;
  assign fifo_count_o = fifo_count;
  assign pixel_x_o = ox;
  assign pixel_y_o = oy;
endmodule
