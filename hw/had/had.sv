// The HAD (4.2.11): takes pixels from the FIFO, keeps CACHE_PAGES pages (one
// of 16 x 1 pixels in the thesis; girtd_pkg::PAGE_*) in its cache, does the Z test and the blend, and swaps pages with the VRAM.
// Rules as models/had (HadPix): Z >= Zb rejected; nf = 0 dropped; nf = 1
// writes R, G, B and Z; 0 < nf < 1 blends R, G, B and keeps Z. Timing in
// base ticks, all run-time inputs: a cache access (read, compare and write in
// one HAD cycle) takes `access_ticks_i`, a blend `blend_ticks_i` more; a page
// miss writes back the page in the new one's cache slot and fetches the new
// one (2 VRAM cycles); the frame's end writes back every page, slot by slot.
// Options (5.2.2 and 7, all off in the thesis' design):
// - write-behind: the old page goes to a register and is written while the
//   new page is in use, so a miss waits for the fetch only;
// - prefetch: while a pixel is being accessed, the page of the pixel at the
//   head of the FIFO (the HAD's address pipeline) is fetched into a second
//   page buffer; a miss on that page then costs no fetch;
// - dirty bits: a page no pixel was written to is not written back.
module had (
    input  logic        clk_i,
    input  logic        rst_ni,
    input  logic [girtd_pkg::TIME_W-1:0] access_ticks_i,
    input  logic [girtd_pkg::TIME_W-1:0] blend_ticks_i,
    input  logic        one_minus_exact_i,  // 1 - nf as 256 - nf (else the inverted bits, 255 - nf)
    input  logic        write_behind_i,
    input  logic        prefetch_i,
    input  logic        dirty_bits_i,
    // FIFO side: the word of girtd_pkg::FIFO_* {X, Y, R, G, B, nf, Z}
    input  logic        fifo_empty_i,
    input  logic [girtd_pkg::FIFO_W-1:0] fifo_data_i,
    output logic        fifo_pop_o,
    // VRAM random port
    output logic        vram_req_o,
    output logic        vram_we_o,
    output logic [girtd_pkg::PAGE_NUMBER_W-1:0] vram_page_o,
    output logic [girtd_pkg::PAGE_PIXELS*girtd_pkg::CELL_W-1:0] vram_wdata_o,
    input  logic [girtd_pkg::PAGE_PIXELS*girtd_pkg::CELL_W-1:0] vram_rdata_i,
    input  logic        vram_busy_i,
    input  logic        vram_done_i,
    // Frame end: write the cache page back and forget it
    input  logic        flush_i,
    output logic        idle_o,
    // Simulation (girtd_backend's tick warp): this edge stands for ticks_i
    // base ticks (1 in hardware), more only over ticks quiet_o promises in
    // which the HAD does nothing but count.
    input  logic [girtd_pkg::LONG_TIME_W-1:0] ticks_i,
    output logic [girtd_pkg::LONG_TIME_W-1:0] quiet_o,
    // Pixel accounting and time (counters, reset with rst_ni)
    output logic [girtd_pkg::COUNT_W-1:0] written_o,
    output logic [girtd_pkg::COUNT_W-1:0] blended_o,
    output logic [girtd_pkg::COUNT_W-1:0] z_rejected_o,
    output logic [girtd_pkg::COUNT_W-1:0] dropped_o,
    output logic [girtd_pkg::COUNT_W-1:0] page_misses_o,
    output logic [girtd_pkg::TICK_COUNT_W-1:0] busy_ticks_o,       // a pixel in hand
    output logic [girtd_pkg::TICK_COUNT_W-1:0] vram_wait_ticks_o   // of those, waiting for a page
);
  // Foreground states; background VRAM work (write-behind drain, prefetch)
  // runs while the HAD is in H_IDLE, H_ACCESS or H_BLEND.
  localparam int SB = girtd_pkg::SCREEN_BITS, XB = girtd_pkg::PAGE_X_BITS, YB = girtd_pkg::PAGE_Y_BITS;
  localparam int NW = girtd_pkg::PAGE_NUMBER_W, IW = girtd_pkg::PAGE_INDEX_W;
  localparam int CW = girtd_pkg::CELL_W, PW = girtd_pkg::PAGE_PIXELS * girtd_pkg::CELL_W;
  localparam int CO = girtd_pkg::COLOR_OUT, ZO = girtd_pkg::Z_OUT, NFW = girtd_pkg::NF_W;

  // The page of a pixel, {Y[SB-1:YB], X[SB-1:XB]}, and its place in the page,
  // {Y[YB-1:0], X[XB-1:0]} (models/layout/rtl_layout.hpp, PageGeometry).
  function automatic logic [NW-1:0] page_number(input logic [SB-1:0] x, input logic [SB-1:0] y);
    page_number = NW'(((32'(y) >> YB) << (SB - XB)) | (32'(x) >> XB));
  endfunction
  function automatic logic [IW-1:0] page_index(input logic [SB-1:0] x, input logic [SB-1:0] y);
    page_index = IW'(((32'(y) & ((1 << YB) - 1)) << XB) | (32'(x) & ((1 << XB) - 1)));
  endfunction

  localparam logic [2:0] H_IDLE = 3'd0, H_WB = 3'd1, H_FETCH = 3'd2, H_ACCESS = 3'd3, H_BLEND = 3'd4,
                         H_FLUSH = 3'd5, H_REFETCH = 3'd6;  // REFETCH: the VRAM was taken between write-back and fetch
  logic [2:0] state_q;
  logic [girtd_pkg::TIME_W-1:0] count_q;
  localparam logic [girtd_pkg::TIME_W-1:0] ONE_TICK = 1, TWO_TICKS = 2;
  logic [girtd_pkg::FIFO_W-1:0] pix_q;
  logic flush_pending_q, use_pf_q;
  logic [girtd_pkg::CACHE_SLOT_W-1:0] flush_slot_q;  // the slot the frame-end flush is at
  // Write-behind register: the old page waiting for its VRAM write.
  logic wb_pending_q;
  logic [NW-1:0] wb_page_q;
  logic [PW-1:0] wb_data_q;
  // Prefetch buffer.
  logic pf_valid_q, pf_loading_q;
  logic [NW-1:0] pf_page_q;
  logic [PW-1:0] pf_data_q;

  logic cache_load, cache_write, cache_invalidate;
  logic head_hit, victim_valid, victim_dirty, flush_valid, flush_dirty;  // victim: the head page's slot
  logic [NW-1:0] victim_page, flush_page;
  logic [PW-1:0] victim_data, flush_data, cache_load_data;
  logic [CW-1:0] cell_new, cell_old;

  // The pixel at the head of the FIFO and the one in hand.
  logic [NW-1:0] head_page, pix_page;
  logic [SB-1:0] head_x, head_y, pix_x, pix_y;
  assign head_x = fifo_data_i[girtd_pkg::FIFO_X_LSB+:SB];
  assign head_y = fifo_data_i[girtd_pkg::FIFO_Y_LSB+:SB];
  assign pix_x = pix_q[girtd_pkg::FIFO_X_LSB+:SB];
  assign pix_y = pix_q[girtd_pkg::FIFO_Y_LSB+:SB];
  assign head_page = page_number(head_x, head_y);
  assign pix_page = page_number(pix_x, pix_y);
  logic [IW-1:0] x;  // the pixel in the page
  logic [CO-1:0] r, g, b;
  logic [NFW-1:0] nf;
  logic [ZO-1:0] z, zb;
  assign x = page_index(pix_x, pix_y);
  assign r = pix_q[girtd_pkg::FIFO_R_LSB+:CO];
  assign g = pix_q[girtd_pkg::FIFO_G_LSB+:CO];
  assign b = pix_q[girtd_pkg::FIFO_B_LSB+:CO];
  assign nf = pix_q[girtd_pkg::FIFO_NF_LSB+:NFW];
  assign z = pix_q[girtd_pkg::FIFO_Z_LSB+:ZO];
  assign zb = cell_old[ZO-1:0];

  pixel_cache u_cache (
      .clk_i, .rst_ni, .head_page_i(head_page), .head_hit_o(head_hit), .head_slot_valid_o(victim_valid),
      .head_slot_dirty_o(victim_dirty), .head_slot_page_o(victim_page), .head_slot_data_o(victim_data),
      .pix_page_i(pix_page), .pix_index_i(x), .pix_cell_o(cell_old), .flush_slot_i(flush_slot_q),
      .flush_valid_o(flush_valid), .flush_dirty_o(flush_dirty), .flush_page_o(flush_page), .flush_data_o(flush_data),
      .invalidate_i(cache_invalidate), .load_i(cache_load), .load_page_i(pix_page), .load_data_i(cache_load_data),
      .write_i(cache_write), .write_data_i(cell_new));

  // Cb = C nf + Cb (1 - nf), CO x NF products keeping the high bits (8 x 8 in the thesis).
  localparam int F = girtd_pkg::NORM_FRAC;
  localparam logic [NFW-1:0] NF_ONE = NFW'(1) << F;
  function automatic logic [CO-1:0] blend(input logic [CO-1:0] c, input logic [CO-1:0] cb, input logic [NFW-1:0] f,
                                          input logic exact);
    logic [NFW-1:0] one_minus;
    logic [CO+1:0] sum;
    one_minus = exact ? NF_ONE - f : {1'b0, ~f[F-1:0]};
    sum = (CO + 2)'((32'(c) * 32'(f)) >> F) + (CO + 2)'((32'(cb) * 32'(one_minus)) >> F);
    blend = sum > (CO + 2)'({CO{1'b1}}) ? '1 : sum[CO-1:0];
  endfunction

  // The outcome of the access in hand. A cell is {R, G, B, Z}.
  logic z_pass, opaque;
  assign z_pass = z < zb;
  assign opaque = nf >= NF_ONE;
  always_comb begin
    if (opaque) cell_new = {r, g, b, z};
    else cell_new = {blend(r, cell_old[ZO+2*CO+:CO], nf, one_minus_exact_i), blend(g, cell_old[ZO+CO+:CO], nf, one_minus_exact_i),
                     blend(b, cell_old[ZO+:CO], nf, one_minus_exact_i), cell_old[ZO-1:0]};
  end

  // ---- Decisions of this tick ----
  logic head_in_pf, must_write_back, flush_write_back, background_ok;
  logic miss_go, miss_wait_pf, flush_go, flush_step, wb_issue, pf_issue;
  assign head_in_pf = pf_page_q == head_page && (pf_valid_q || pf_loading_q);
  // On a miss the page in the head's slot goes back; at the frame's end, each slot's.
  assign must_write_back = victim_valid && (victim_dirty || !dirty_bits_i);
  assign flush_write_back = flush_valid && (flush_dirty || !dirty_bits_i);
  assign background_ok = state_q == H_IDLE || state_q == H_ACCESS || state_q == H_BLEND;
  // A miss proceeds when the VRAM is free and no write-behind is pending; a
  // miss on the page being prefetched waits for it instead.
  assign miss_wait_pf = head_in_pf && pf_loading_q;
  // A pending flush waits for the FIFO to drain; pixels keep flowing meanwhile.
  assign miss_go = state_q == H_IDLE && !fifo_empty_i && !head_hit && !miss_wait_pf &&
                   !vram_busy_i && !wb_pending_q && !pf_loading_q;
  assign flush_step = state_q == H_IDLE && flush_pending_q && fifo_empty_i && !vram_busy_i && !wb_pending_q &&
                      !pf_loading_q;
  assign flush_go = flush_step && flush_write_back;
  assign wb_issue = background_ok && wb_pending_q && !vram_busy_i;
  // Prefetch the head's page while the HAD is busy with a pixel of another page.
  assign pf_issue = prefetch_i && background_ok && state_q != H_IDLE && !wb_pending_q && !vram_busy_i &&
                    !pf_valid_q && !pf_loading_q && !fifo_empty_i && victim_valid && !head_hit;

  always_comb begin
    fifo_pop_o = 1'b0;
    vram_req_o = 1'b0;
    vram_we_o = 1'b0;
    vram_page_o = victim_page;
    vram_wdata_o = victim_data;
    cache_load = 1'b0;
    cache_load_data = use_pf_q ? pf_data_q : vram_rdata_i;
    cache_write = 1'b0;
    cache_invalidate = 1'b0;
    if (wb_issue) begin
      vram_req_o = 1'b1;
      vram_we_o = 1'b1;
      vram_page_o = wb_page_q;
      vram_wdata_o = wb_data_q;
    end else if (pf_issue) begin
      vram_req_o = 1'b1;
      vram_page_o = head_page;
    end
    unique case (state_q)
      H_IDLE: begin
        if (!fifo_empty_i && head_hit) fifo_pop_o = 1'b1;
        else if (miss_go) begin
          fifo_pop_o = 1'b1;
          if (must_write_back && !write_behind_i) begin  // write the old page back first
            vram_req_o = 1'b1;
            vram_we_o = 1'b1;
          end else if (!(pf_valid_q && pf_page_q == head_page)) begin  // fetch now
            vram_req_o = 1'b1;
            vram_page_o = head_page;
          end
        end else if (flush_go) begin
          vram_req_o = 1'b1;
          vram_we_o = 1'b1;
          vram_page_o = flush_page;
          vram_wdata_o = flush_data;
        end
      end
      // The fetch follows the write-back in the same tick, unless the VRAM is
      // taken then (a refresh or scan-out cycle): then it waits in H_REFETCH.
      H_WB, H_REFETCH: if ((state_q == H_REFETCH || vram_done_i) && !use_pf_q && !vram_busy_i) begin
        vram_req_o = 1'b1;
        vram_page_o = pix_page;
      end
      H_FETCH: cache_load = use_pf_q || vram_done_i;
      H_ACCESS: cache_write = count_q == ONE_TICK && z_pass && nf != '0 && (opaque || blend_ticks_i == 0);
      H_BLEND: cache_write = count_q == ONE_TICK;
      H_FLUSH: cache_invalidate = vram_done_i || !flush_write_back;
      default: ;
    endcase
  end

  // The flush goes on to the next slot; after the last, it is done.
  localparam int PAGES = girtd_pkg::CACHE_PAGES;
  task automatic next_flush_slot();
    if (32'(flush_slot_q) == PAGES - 1) begin
      flush_slot_q <= '0;
      flush_pending_q <= 1'b0;
      pf_valid_q <= 1'b0;
    end else begin
      flush_slot_q <= flush_slot_q + 1'b1;
    end
  endtask

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q <= H_IDLE;
      flush_pending_q <= 1'b0;
      wb_pending_q <= 1'b0;
      pf_valid_q <= 1'b0;
      pf_loading_q <= 1'b0;
      flush_slot_q <= '0;
      use_pf_q <= 1'b0;
      {written_o, blended_o, z_rejected_o, dropped_o, page_misses_o} <= '0;
      busy_ticks_o <= '0;
      vram_wait_ticks_o <= '0;
    end else begin
      if (flush_i) flush_pending_q <= 1'b1;
      if (wb_issue) wb_pending_q <= 1'b0;
      if (pf_issue) begin
        pf_loading_q <= 1'b1;
        pf_page_q <= head_page;
      end
      // A background fetch ends while the foreground is in no VRAM state.
      if (pf_loading_q && vram_done_i && background_ok) begin
        pf_loading_q <= 1'b0;
        pf_valid_q <= 1'b1;
        pf_data_q <= vram_rdata_i;
      end
      if (state_q != H_IDLE || fifo_pop_o) busy_ticks_o <= busy_ticks_o + girtd_pkg::TICK_COUNT_W'(ticks_i);
      if (state_q == H_WB || state_q == H_REFETCH || (state_q == H_FETCH && !use_pf_q) ||
          (state_q == H_IDLE && !fifo_empty_i && !head_hit && !fifo_pop_o))
        vram_wait_ticks_o <= vram_wait_ticks_o + girtd_pkg::TICK_COUNT_W'(ticks_i);
      unique case (state_q)
        H_IDLE: begin
          if (fifo_pop_o) pix_q <= fifo_data_i;
          if (fifo_pop_o && head_hit) begin
            state_q <= H_ACCESS;  // the pop tick is the access's first
            count_q <= access_ticks_i <= TWO_TICKS ? ONE_TICK : access_ticks_i - 1'b1;
          end else if (miss_go) begin
            page_misses_o <= page_misses_o + 1'b1;
            // The prefetched page is used if it is the one wanted, else dropped.
            use_pf_q <= pf_valid_q && pf_page_q == head_page;
            pf_valid_q <= 1'b0;
            if (must_write_back && !write_behind_i) state_q <= H_WB;
            else begin
              if (must_write_back) begin  // the old page goes to the write-behind register
                wb_pending_q <= 1'b1;
                wb_page_q <= victim_page;
                wb_data_q <= victim_data;
              end
              state_q <= H_FETCH;
            end
          end else if (flush_step) begin
            if (flush_valid) state_q <= H_FLUSH;  // written back there (or only forgotten: clean)
            else next_flush_slot();
          end
        end
        H_WB: if (vram_done_i) state_q <= use_pf_q || !vram_busy_i ? H_FETCH : H_REFETCH;
        H_REFETCH: if (!vram_busy_i) state_q <= H_FETCH;
        H_FETCH: if (use_pf_q || vram_done_i) begin
          state_q <= H_ACCESS;
          use_pf_q <= 1'b0;
          count_q <= access_ticks_i == 0 ? ONE_TICK : access_ticks_i;
        end
        H_ACCESS: begin
          if (count_q > ONE_TICK) count_q <= count_q - girtd_pkg::TIME_W'(ticks_i);
          else if (!z_pass) begin
            z_rejected_o <= z_rejected_o + 1'b1;
            state_q <= H_IDLE;
          end else if (nf == '0) begin
            dropped_o <= dropped_o + 1'b1;
            state_q <= H_IDLE;
          end else if (opaque) begin
            written_o <= written_o + 1'b1;
            state_q <= H_IDLE;
          end else begin
            blended_o <= blended_o + 1'b1;
            if (blend_ticks_i == 0) state_q <= H_IDLE;
            else begin
              state_q <= H_BLEND;
              count_q <= blend_ticks_i;
            end
          end
        end
        H_BLEND: begin
          if (count_q > ONE_TICK) count_q <= count_q - girtd_pkg::TIME_W'(ticks_i);
          else state_q <= H_IDLE;
        end
        H_FLUSH: if (vram_done_i || !flush_write_back) begin
          state_q <= H_IDLE;
          next_flush_slot();
        end
        default: state_q <= H_IDLE;
      endcase
    end
  end

  // Ticks from this one on in which nothing is decided: no pop, no VRAM
  // request, no cache write, no state change. Waits for the VRAM last until
  // its own quiet_o runs out (a page arrives, the port frees); an access or a
  // blend until its count reaches one.
  localparam logic [girtd_pkg::LONG_TIME_W-1:0] FOREVER = '1;
  always_comb begin
    unique case (state_q)
      H_IDLE: quiet_o = fifo_pop_o || miss_go || flush_step || wb_issue ? '0 : FOREVER;
      H_ACCESS, H_BLEND:
        quiet_o = count_q > ONE_TICK && !wb_issue && !pf_issue ? girtd_pkg::LONG_TIME_W'(count_q) - 1'b1 : '0;
      H_WB: quiet_o = vram_done_i ? '0 : FOREVER;
      H_REFETCH: quiet_o = vram_busy_i ? FOREVER : '0;
      H_FETCH: quiet_o = use_pf_q || vram_done_i ? '0 : FOREVER;
      H_FLUSH: quiet_o = vram_done_i || !flush_write_back ? '0 : FOREVER;
      default: quiet_o = '0;
    endcase
  end

  assign idle_o = state_q == H_IDLE && !flush_pending_q && !wb_pending_q && !pf_loading_q;

`ifdef FORMAL_HAD  // tools/girtd formal, when this module is the one proven
`include "had_formal.svh"
`endif
endmodule
