// The HAD (4.2.11): takes pixels from the FIFO, keeps one 16-pixel page in
// its cache, does the Z test and the blend, and swaps pages with the VRAM.
// Rules as models/had (HadPix): Z >= Zb rejected; nf = 0 dropped; nf = 1
// writes R, G, B and Z; 0 < nf < 1 blends R, G, B and keeps Z. Timing in
// base ticks, all run-time inputs: a cache access (read, compare and write in
// one HAD cycle) takes `access_ticks_i`, a blend `blend_ticks_i` more; a page
// miss writes the page back and fetches the new one (2 VRAM cycles).
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
    input  logic [15:0] access_ticks_i,
    input  logic [15:0] blend_ticks_i,
    input  logic        one_minus_exact_i,  // 1 - nf as 256 - nf (else the inverted bits, 255 - nf)
    input  logic        write_behind_i,
    input  logic        prefetch_i,
    input  logic        dirty_bits_i,
    // FIFO side: {x10, y10, r8, g8, b8, nf9, z16}
    input  logic        fifo_empty_i,
    input  logic [68:0] fifo_data_i,
    output logic        fifo_pop_o,
    // VRAM random port
    output logic        vram_req_o,
    output logic        vram_we_o,
    output logic [15:0] vram_page_o,
    output logic [16*40-1:0] vram_wdata_o,
    input  logic [16*40-1:0] vram_rdata_i,
    input  logic        vram_busy_i,
    input  logic        vram_done_i,
    // Frame end: write the cache page back and forget it
    input  logic        flush_i,
    output logic        idle_o,
    // Pixel accounting and time (counters, reset with rst_ni)
    output logic [31:0] written_o,
    output logic [31:0] blended_o,
    output logic [31:0] z_rejected_o,
    output logic [31:0] dropped_o,
    output logic [31:0] page_misses_o,
    output logic [47:0] busy_ticks_o,       // a pixel in hand
    output logic [47:0] vram_wait_ticks_o   // of those, waiting for a page
);
  // Foreground states; background VRAM work (write-behind drain, prefetch)
  // runs while the HAD is in H_IDLE, H_ACCESS or H_BLEND.
  localparam logic [2:0] H_IDLE = 3'd0, H_WB = 3'd1, H_FETCH = 3'd2, H_ACCESS = 3'd3, H_BLEND = 3'd4,
                         H_FLUSH = 3'd5, H_REFETCH = 3'd6;  // REFETCH: the VRAM was taken between write-back and fetch
  logic [2:0] state_q;
  logic [15:0] count_q;
  logic [68:0] pix_q;
  logic flush_pending_q, dirty_q, use_pf_q;
  // Write-behind register: the old page waiting for its VRAM write.
  logic wb_pending_q;
  logic [15:0] wb_page_q;
  logic [16*40-1:0] wb_data_q;
  // Prefetch buffer.
  logic pf_valid_q, pf_loading_q;
  logic [15:0] pf_page_q;
  logic [16*40-1:0] pf_data_q;

  logic cache_valid, cache_load, cache_write, cache_invalidate;
  logic [15:0] cache_page;
  logic [16*40-1:0] cache_data, cache_load_data;
  logic [39:0] cell_new, cell_old;

  // The pixel at the head of the FIFO and the one in hand.
  logic [15:0] head_page, pix_page;  // A4-A19: Y and the top 6 bits of X
  assign head_page = {fifo_data_i[58:49], fifo_data_i[68:63]};
  assign pix_page = {pix_q[58:49], pix_q[68:63]};
  logic [3:0] x;  // A0-A3: the pixel in the page
  logic [7:0] r, g, b;
  logic [8:0] nf;
  logic [15:0] z, zb;
  assign {x, r, g, b, nf, z} = {pix_q[62:59], pix_q[48:41], pix_q[40:33], pix_q[32:25], pix_q[24:16], pix_q[15:0]};
  assign cell_old = cache_data[x*40+:40];
  assign zb = cell_old[15:0];

  pixel_cache u_cache (
      .clk_i, .rst_ni, .invalidate_i(cache_invalidate), .load_i(cache_load), .load_page_i(pix_page),
      .load_data_i(cache_load_data), .write_i(cache_write), .write_index_i(x), .write_data_i(cell_new),
      .valid_o(cache_valid), .page_o(cache_page), .data_o(cache_data));

  // Cb = C nf + Cb (1 - nf), 8 x 8 products keeping the high byte.
  function automatic logic [7:0] blend(input logic [7:0] c, input logic [7:0] cb, input logic [8:0] f,
                                       input logic exact);
    logic [8:0] one_minus;
    logic [9:0] sum;
    one_minus = exact ? 9'd256 - f : {1'b0, ~f[7:0]};
    sum = 10'((17'(c) * 17'(f)) >> 8) + 10'((17'(cb) * 17'(one_minus)) >> 8);
    blend = sum > 10'd255 ? 8'd255 : sum[7:0];
  endfunction

  // The outcome of the access in hand.
  logic z_pass, opaque;
  assign z_pass = z < zb;
  assign opaque = nf >= 9'd256;
  always_comb begin
    if (opaque) cell_new = {r, g, b, z};
    else cell_new = {blend(r, cell_old[39:32], nf, one_minus_exact_i), blend(g, cell_old[31:24], nf, one_minus_exact_i),
                     blend(b, cell_old[23:16], nf, one_minus_exact_i), cell_old[15:0]};
  end

  // ---- Decisions of this tick ----
  logic head_hit, head_in_pf, must_write_back, background_ok;
  logic miss_go, miss_wait_pf, flush_go, wb_issue, pf_issue;
  assign head_hit = cache_valid && cache_page == head_page;
  assign head_in_pf = pf_page_q == head_page && (pf_valid_q || pf_loading_q);
  assign must_write_back = cache_valid && (dirty_q || !dirty_bits_i);
  assign background_ok = state_q == H_IDLE || state_q == H_ACCESS || state_q == H_BLEND;
  // A miss proceeds when the VRAM is free and no write-behind is pending; a
  // miss on the page being prefetched waits for it instead.
  assign miss_wait_pf = head_in_pf && pf_loading_q;
  // A pending flush waits for the FIFO to drain; pixels keep flowing meanwhile.
  assign miss_go = state_q == H_IDLE && !fifo_empty_i && !head_hit && !miss_wait_pf &&
                   !vram_busy_i && !wb_pending_q && !pf_loading_q;
  assign flush_go = state_q == H_IDLE && flush_pending_q && fifo_empty_i && !vram_busy_i && !wb_pending_q &&
                    !pf_loading_q && must_write_back;
  assign wb_issue = background_ok && wb_pending_q && !vram_busy_i;
  // Prefetch the head's page while the HAD is busy with a pixel of another page.
  assign pf_issue = prefetch_i && background_ok && state_q != H_IDLE && !wb_pending_q && !vram_busy_i &&
                    !pf_valid_q && !pf_loading_q && !fifo_empty_i && cache_valid && head_page != cache_page;

  always_comb begin
    fifo_pop_o = 1'b0;
    vram_req_o = 1'b0;
    vram_we_o = 1'b0;
    vram_page_o = cache_page;
    vram_wdata_o = cache_data;
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
        end
      end
      // The fetch follows the write-back in the same tick, unless the VRAM is
      // taken then (a refresh or scan-out cycle): then it waits in H_REFETCH.
      H_WB, H_REFETCH: if ((state_q == H_REFETCH || vram_done_i) && !use_pf_q && !vram_busy_i) begin
        vram_req_o = 1'b1;
        vram_page_o = pix_page;
      end
      H_FETCH: cache_load = use_pf_q || vram_done_i;
      H_ACCESS: cache_write = count_q == 16'd1 && z_pass && nf != '0 && (opaque || blend_ticks_i == 0);
      H_BLEND: cache_write = count_q == 16'd1;
      H_FLUSH: cache_invalidate = vram_done_i || !must_write_back;
      default: ;
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q <= H_IDLE;
      flush_pending_q <= 1'b0;
      wb_pending_q <= 1'b0;
      pf_valid_q <= 1'b0;
      pf_loading_q <= 1'b0;
      dirty_q <= 1'b0;
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
      if (cache_write) dirty_q <= 1'b1;
      if (cache_load) dirty_q <= 1'b0;
      if (state_q != H_IDLE || fifo_pop_o) busy_ticks_o <= busy_ticks_o + 1'b1;
      if (state_q == H_WB || state_q == H_REFETCH || (state_q == H_FETCH && !use_pf_q) ||
          (state_q == H_IDLE && !fifo_empty_i && !head_hit && !fifo_pop_o))
        vram_wait_ticks_o <= vram_wait_ticks_o + 1'b1;
      unique case (state_q)
        H_IDLE: begin
          if (fifo_pop_o) pix_q <= fifo_data_i;
          if (fifo_pop_o && head_hit) begin
            state_q <= H_ACCESS;  // the pop tick is the access's first
            count_q <= access_ticks_i <= 16'd2 ? 16'd1 : access_ticks_i - 1'b1;
          end else if (miss_go) begin
            page_misses_o <= page_misses_o + 1'b1;
            // The prefetched page is used if it is the one wanted, else dropped.
            use_pf_q <= pf_valid_q && pf_page_q == head_page;
            pf_valid_q <= 1'b0;
            if (must_write_back && !write_behind_i) state_q <= H_WB;
            else begin
              if (must_write_back) begin  // the old page goes to the write-behind register
                wb_pending_q <= 1'b1;
                wb_page_q <= cache_page;
                wb_data_q <= cache_data;
              end
              state_q <= H_FETCH;
            end
          end else if (flush_go) state_q <= H_FLUSH;
          else if (flush_pending_q && fifo_empty_i && !vram_busy_i && !wb_pending_q && !pf_loading_q) begin
            flush_pending_q <= 1'b0;  // nothing (more) to write back
            pf_valid_q <= 1'b0;
            if (cache_valid) state_q <= H_FLUSH;
          end
        end
        H_WB: if (vram_done_i) state_q <= use_pf_q || !vram_busy_i ? H_FETCH : H_REFETCH;
        H_REFETCH: if (!vram_busy_i) state_q <= H_FETCH;
        H_FETCH: if (use_pf_q || vram_done_i) begin
          state_q <= H_ACCESS;
          use_pf_q <= 1'b0;
          count_q <= access_ticks_i == 0 ? 16'd1 : access_ticks_i;
        end
        H_ACCESS: begin
          if (count_q > 16'd1) count_q <= count_q - 1'b1;
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
          if (count_q > 16'd1) count_q <= count_q - 1'b1;
          else state_q <= H_IDLE;
        end
        H_FLUSH: if (vram_done_i || !must_write_back) begin
          state_q <= H_IDLE;
          flush_pending_q <= 1'b0;
          pf_valid_q <= 1'b0;
        end
        default: state_q <= H_IDLE;
      endcase
    end
  end

  assign idle_o = state_q == H_IDLE && !flush_pending_q && !wb_pending_q && !pf_loading_q;
endmodule
