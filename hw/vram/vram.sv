// Video memory (4.2.11.4, 5.2.2): 1M x 64 bits = two RGB buffers and one Z
// per pixel, on PAGE_PIXELS boards (16 in the thesis: banks = X[3:0]), so one
// random-port cycle moves a whole page. A pixel's word address is {page
// number, pixel in the page} (girtd_pkg::PAGE_*). Behavioural: the array is read and written at the end
// of a cycle of `cycle_ticks_i`; the frame clear goes through the serial port
// and takes `clear_ticks_i`. The array is readable (public_flat_rd: never written from outside, so no logic is re-evaluated for it on every eval) for the testbench backdoor
// and kept out of waveforms.
// Word: RGB buffer 0, RGB buffer 1, Z (girtd_pkg::VRAM_*).
module vram #(
    localparam int PW = girtd_pkg::PAGE_PIXELS * girtd_pkg::CELL_W,
    localparam int RGB = 3 * girtd_pkg::COLOR_OUT
) (
    input  logic            clk_i,
    input  logic            rst_ni,
    input  logic [girtd_pkg::TIME_W-1:0]      cycle_ticks_i,
    input  logic [girtd_pkg::LONG_TIME_W-1:0] clear_ticks_i,
    // Refresh and video scan-out (option): every steal_period_ticks_i ticks
    // (0 = never) one random-port cycle is taken for a serial transfer.
    input  logic [girtd_pkg::LONG_TIME_W-1:0] steal_period_ticks_i,
    // Random port: one page per request
    input  logic            req_i,
    input  logic            we_i,
    input  logic [girtd_pkg::PAGE_NUMBER_W-1:0] page_i,
    input  logic [PW-1:0]   wdata_i,  // per pixel {back R, G, B, Z}
    output logic [PW-1:0]   rdata_o,
    output logic            busy_o,   // no request can be taken this tick
    output logic            done_o,   // the tick a page operation ends (a fetch's data is valid)
    // Frame control
    input  logic            clear_i,  // back buffer <- background, Z <- FFFF
    input  logic [RGB-1:0]  background_i,
    input  logic            swap_i,
    output logic            front_o,  // the buffer shown: 0 = bits 63:40
    // Simulation (girtd_backend's tick warp): this edge stands for ticks_i
    // base ticks (1 in hardware), more only over ticks quiet_o promises in
    // which the VRAM does nothing but count down its cycle and the steal period.
    input  logic [girtd_pkg::LONG_TIME_W-1:0] ticks_i,
    output logic [girtd_pkg::LONG_TIME_W-1:0] quiet_o
);
  localparam int LT = girtd_pkg::LONG_TIME_W, N = girtd_pkg::PAGE_PIXELS, CW = girtd_pkg::CELL_W;
  localparam int IW = girtd_pkg::PAGE_INDEX_W, ZO = girtd_pkg::Z_OUT;
  localparam int B0 = girtd_pkg::VRAM_RGB0_LSB, B1 = girtd_pkg::VRAM_RGB1_LSB, ZL = girtd_pkg::VRAM_Z_LSB;
  localparam logic [ZO-1:0] Z_CLEAR = ZO'(girtd_pkg::Z_CLEAR);
  logic [girtd_pkg::VRAM_W-1:0] mem[1 << (2 * girtd_pkg::SCREEN_BITS)]  /*verilator public_flat_rd*/;
  logic [LT-1:0] left_q;  // ticks left in the current operation
  logic busy_q, we_q, front_q, clearing_q, stealing_q;
  logic [girtd_pkg::PAGE_NUMBER_W-1:0] page_q;
  logic [PW-1:0] wdata_q;
  logic [RGB-1:0] bg_q;
  logic finishing;
  logic [LT-1:0] steal_count_q;
  logic [7:0] steals_owed_q;  // stolen cycles come due even while the port is busy
  logic steal_due_q;
  logic buf_q;  // the back buffer of the operation in flight, fixed when it is accepted
  assign steal_due_q = steals_owed_q != '0;

  // An operation ends on the tick its count reaches 1; a new one can be
  // accepted on that same tick, so back-to-back cycles leave no gap.
  logic port_busy, clear_pending_q, accepting;
  assign finishing = busy_q && left_q == LT'(1);
  assign port_busy = busy_q && !finishing;
  // A page request is taken this tick (after any due stolen cycle or clear).
  assign accepting = !port_busy && !steal_due_q && !clear_pending_q && !clear_i && req_i;
  // A due stolen cycle or a pending clear goes before any request. (The
  // clear's own request tick is not in it: the harness asks for a clear only
  // with the back end idle, and no logic hangs on the clear_i input.)
  assign busy_o = port_busy || steal_due_q || clear_pending_q;
  assign done_o = finishing && !clearing_q && !stealing_q;
  assign front_o = front_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      busy_q <= 1'b0;
      front_q <= 1'b0;
      clearing_q <= 1'b0;
      stealing_q <= 1'b0;
      clear_pending_q <= 1'b0;
      steal_count_q <= '0;
      steals_owed_q <= '0;
      left_q <= '0;
    end else begin
      if (swap_i) front_q <= !front_q;
      if (steal_period_ticks_i != 0) begin
        if (steal_count_q + ticks_i >= steal_period_ticks_i) steal_count_q <= '0;
        else steal_count_q <= steal_count_q + ticks_i;
      end
      // Owed steals: one more when the period elapses, one less when a steal starts.
      steals_owed_q <= steals_owed_q + 8'(steal_period_ticks_i != 0 && steal_count_q + 1'b1 >= steal_period_ticks_i &&
                                          steals_owed_q != 8'hFF) - 8'(!port_busy && steal_due_q);
      if (busy_q) left_q <= left_q - ticks_i;
      if (finishing) begin
        busy_q <= 1'b0;
        clearing_q <= 1'b0;
        stealing_q <= 1'b0;
      end
      if (clear_i) clear_pending_q <= 1'b1;
      if (!port_busy && steal_due_q) begin  // a stolen cycle goes first and moves no pixel data
        busy_q <= 1'b1;
        we_q <= 1'b0;
        left_q <= cycle_ticks_i == 0 ? LT'(1) : LT'(cycle_ticks_i);
        stealing_q <= 1'b1;
      end else if (!port_busy && (clear_pending_q || clear_i)) begin
        clear_pending_q <= 1'b0;
        busy_q <= 1'b1;
        clearing_q <= 1'b1;
        buf_q <= !front_q;
        bg_q <= background_i;
        left_q <= clear_ticks_i == 0 ? LT'(1) : clear_ticks_i;
      end else if (accepting) begin
        busy_q <= 1'b1;
        buf_q <= !front_q;
        we_q <= we_i;
        page_q <= page_i;
        wdata_q <= wdata_i;
        left_q <= cycle_ticks_i == 0 ? LT'(1) : LT'(cycle_ticks_i);
      end
    end
  end

`ifndef SYNTHESIS
  // busy_o does not cover the clear's own request tick (see above).
  always_ff @(posedge clk_i)
    if (rst_ni && clear_i && req_i) $error("vram: a page request on the tick a clear is asked for (it would be lost)");
`endif

  // Quiet ticks: before the tick an operation finishes, and, idle, until
  // something is asked for; in both, before the tick a stolen cycle comes due.
  localparam logic [LT-1:0] FOREVER = '1;
  logic [LT-1:0] port_quiet, steal_quiet;
  assign port_quiet = busy_q ? (finishing ? '0 : left_q - 1'b1) : (steal_due_q || clear_pending_q || req_i ? '0 : FOREVER);
  assign steal_quiet = steal_period_ticks_i == 0 ? FOREVER
                     : steal_count_q + 1'b1 >= steal_period_ticks_i ? '0 : steal_period_ticks_i - 1'b1 - steal_count_q;
  assign quiet_o = port_quiet < steal_quiet ? port_quiet : steal_quiet;

  // The array itself: behavioural, written at the end of an operation and
  // read when a fetch is taken (nothing writes the page while it is in
  // flight: one operation at a time, stolen cycles move no data), after a
  // write ending on the same tick. Blocking writes inside loops (Verilator
  // cannot schedule delayed ones to an array in a loop).
  logic [PW-1:0] rdata_q, fetched;
  /* verilator lint_off BLKSEQ */
  always_ff @(posedge clk_i) begin
    if (rst_ni && finishing && !stealing_q) begin
      if (clearing_q) begin
        for (int a = 0; a < (1 << (2 * girtd_pkg::SCREEN_BITS)); a++) begin
          if (!buf_q) mem[a][B0+:RGB] = bg_q;
          else mem[a][B1+:RGB] = bg_q;
          mem[a][ZL+:ZO] = Z_CLEAR;
        end
      end else if (we_q) begin
        for (int i = 0; i < N; i++) begin
          if (!buf_q) mem[{page_q, IW'(i)}][B0+:RGB] = wdata_q[i*CW+ZO+:RGB];
          else mem[{page_q, IW'(i)}][B1+:RGB] = wdata_q[i*CW+ZO+:RGB];
          mem[{page_q, IW'(i)}][ZL+:ZO] = wdata_q[i*CW+:ZO];
        end
      end
    end
    // Read data of the page being fetched: the back buffer and Z.
    if (rst_ni && accepting && !we_i) begin
      for (int i = 0; i < N; i++) begin
        fetched[i*CW+:CW] = front_q ? {mem[{page_i, IW'(i)}][B0+:RGB], mem[{page_i, IW'(i)}][ZL+:ZO]}
                                    : {mem[{page_i, IW'(i)}][B1+:RGB], mem[{page_i, IW'(i)}][ZL+:ZO]};
      end
      rdata_q <= fetched;
    end
  end
  /* verilator lint_on BLKSEQ */
  assign rdata_o = rdata_q;

`ifdef FORMAL_VRAM  // tools/girtd formal, when this module is the one proven
`include "vram_formal.svh"
`endif
endmodule
