-- robowire dissector runtime (the fixed part; the table P above is generated).
-- Wireshark 4.0 or later, Lua 5.2.

local proto = Proto(P.name, P.title .. " (robowire)")
local hf = {}
local pf_message = ProtoField.string(P.name .. ".message", "Message")
local pf_noise = ProtoField.uint32(P.name .. ".noise", "Noise bytes skipped")
local pf_text = ProtoField.string(P.name .. ".json", "Reassembled text")
local pf_reassembled_frames = ProtoField.uint32(P.name .. ".reassembled_frames", "Reassembled from frames")
local all_fields = { pf_message, pf_noise }
if P.multiframe then
    all_fields[#all_fields + 1] = pf_text
    all_fields[#all_fields + 1] = pf_reassembled_frames
end

local ex_range = ProtoExpert.new(P.name .. ".out_of_range", "Value outside the valid range",
    expert.group.PROTOCOL, expert.severity.WARN)
local ex_enum = ProtoExpert.new(P.name .. ".invalid_enum", "Invalid enumeration value",
    expert.group.PROTOCOL, expert.severity.WARN)
local ex_length = ProtoExpert.new(P.name .. ".bad_length", "Wrong length",
    expert.group.PROTOCOL, expert.severity.WARN)
local ex_unknown = ProtoExpert.new(P.name .. ".unknown_command", "Unknown command",
    expert.group.PROTOCOL, expert.severity.WARN)
local ex_fixed = ProtoExpert.new(P.name .. ".bad_fixed_byte", "Wrong fixed byte",
    expert.group.PROTOCOL, expert.severity.WARN)
proto.experts = { ex_range, ex_enum, ex_length, ex_unknown, ex_fixed }

local scalar = {
    u8 = ProtoField.uint8, i8 = ProtoField.int8, u16le = ProtoField.uint16, i16le = ProtoField.int16,
    u32le = ProtoField.uint32, i32le = ProtoField.int32,
}
local sizes = { u8 = 1, i8 = 1, u16le = 2, i16le = 2, u32le = 4, i32le = 4, f32le = 4, bits = 1 }

-- One ProtoField per table field, named <protocol>.<message>.<field>[.<field>...].
local function declare(prefix, list)
    for _, f in ipairs(list) do
        local abbr = prefix .. "." .. f.n
        if f.k == "record" then
            f.pf = ProtoField.none(abbr, f.n)
            declare(abbr, f.f)
        elseif f.k == "bits" then
            local mask = bit32.lshift(bit32.lshift(1, f.w) - 1, f.lo)
            f.pf = ProtoField.uint8(abbr, f.n, base.DEC, f.e, mask)
        elseif f.k == "text" then
            f.pf = ProtoField.string(abbr, f.n)
        elseif f.k == "tail" then
            f.pf = ProtoField.bytes(abbr, f.n)
        elseif f.k == "f32le" then
            f.pf = ProtoField.float(abbr, f.n)
        else
            f.pf = scalar[f.k](abbr, f.n, base.DEC, f.e)
        end
        all_fields[#all_fields + 1] = f.pf
        for _, b in ipairs(f.fb or {}) do -- named bits of a flag byte: {lo, width, name, values}
            local mask = bit32.lshift(bit32.lshift(1, b[2]) - 1, b[1])
            if b[2] == 1 then
                b.pf = ProtoField.bool(abbr .. "." .. b[3], b[3], 8, nil, mask)
            else
                b.pf = ProtoField.uint8(abbr .. "." .. b[3], b[3], base.DEC, next(b[4]) and b[4] or nil, mask)
            end
            all_fields[#all_fields + 1] = b.pf
        end
        if f.u then
            f.pfv = ProtoField.double(abbr .. ".value", f.n .. " [" .. f.u .. "]")
            all_fields[#all_fields + 1] = f.pfv
        end
    end
end
for _, m in ipairs(P.messages) do declare(P.name .. "." .. m.n, m.f) end
proto.fields = all_fields

local function enum_names(e)
    local keys = {}
    for k in pairs(e) do keys[#keys + 1] = k end
    table.sort(keys)
    local out = {}
    for _, k in ipairs(keys) do out[#out + 1] = e[k] .. " (" .. k .. ")" end
    return table.concat(out, ", ")
end

-- Adds element i of field f at byte `off`; `path` names it in expert texts.
local add_fields
local function add_element(tree, tvb, f, off, len, path, index)
    if f.k == "record" then
        local item = tree:add(f.pf, tvb(off, f.es))
        if index then item:set_text(f.n .. "[" .. index .. "]") end
        add_fields(item, tvb, off, f.f, len, path)
        return
    end
    if f.k == "text" then
        local r = tvb(off, f.es)
        local s = r:stringz()
        local item = tree:add(f.pf, r, s)
        for i = #s, f.es - 1 do
            if r(i, 1):uint() ~= 0 then
                item:add_proto_expert_info(ex_length, path .. ": padding after the text is not zero")
                break
            end
        end
        return
    end
    local r = tvb(off, sizes[f.k])
    local item, v
    if f.k == "u8" then
        v = r:uint(); item = tree:add(f.pf, r)
        for _, b in ipairs(f.fb or {}) do item:add(b.pf, r) end
    elseif f.k == "i8" then
        v = r:int(); item = tree:add(f.pf, r)
    elseif f.k == "bits" then
        v = bit32.extract(r:uint(), f.lo, f.w); item = tree:add(f.pf, r)
    elseif f.k == "f32le" then
        v = r:le_float(); item = tree:add_le(f.pf, r)
    elseif f.k == "u16le" or f.k == "u32le" then
        v = r:le_uint(); item = tree:add_le(f.pf, r)
    else
        v = r:le_int(); item = tree:add_le(f.pf, r)
    end
    if index and not f.e and f.k ~= "bits" and f.k ~= "f32le" then
        item:set_text(f.n .. "[" .. index .. "]: " .. v)
    end
    if f.e and f.e[v] == nil then
        item:add_proto_expert_info(ex_enum, path .. " = " .. v .. " is not valid (valid: " .. enum_names(f.e) .. ")")
    elseif f.r and (v < f.r[1] or v > f.r[2]) then
        item:add_proto_expert_info(ex_range, path .. " = " .. v .. " is outside " .. f.r[1] .. ".." .. f.r[2])
    end
    if f.u then
        item:add(f.pfv, r, v * f.s + f.a):set_generated()
    end
end

add_fields = function(tree, tvb, base_off, list, len, prefix)
    for _, f in ipairs(list) do
        local off = base_off + f.o
        local path = prefix .. "." .. f.n
        if f.k == "tail" then
            local n = math.min(len - off, f.sz)
            if n > 0 then tree:add(f.pf, tvb(off, n)) end
        elseif f.opt and len <= off then
            return -- an optional block and everything after it absent
        elseif off + f.sz > len then
            tree:add_proto_expert_info(ex_length, path .. ": " .. (len - off) .. " of its " .. f.sz .. " bytes present")
            return
        else
            for i = 0, f.c - 1 do
                if f.c > 1 then
                    add_element(tree, tvb, f, off + i * f.es, len, path .. "[" .. i .. "]", i)
                else
                    add_element(tree, tvb, f, off, len, path, nil)
                end
            end
        end
    end
end

local function is_key(o)
    for _, k in ipairs(P.key) do if k == o then return true end end
    return false
end

-- The message whose key bytes (the command) match, for this direction.
local function pick(tvb, dir)
    local len = tvb:len()
    local fallback
    for _, m in ipairs(P.messages) do
        if dir == nil or m.d == nil or m.d == dir then
            local keyed, match = false, true
            for _, x in ipairs(m.fx) do
                if is_key(x[1]) then
                    keyed = true
                    if x[1] >= len or tvb(x[1], 1):uint() ~= x[2] then match = false end
                end
            end
            if keyed and match then return m end
            if not keyed and not fallback then fallback = m end
        end
    end
    return fallback
end

local function key_text(tvb)
    local parts = {}
    for _, k in ipairs(P.key) do
        if k < tvb:len() then parts[#parts + 1] = string.format("0x%02x", tvb(k, 1):uint()) end
    end
    return table.concat(parts, " ")
end

-- Dissects one message in `tvb` (the whole of it); returns the message or nil.
local function dissect_message(tvb, pinfo, tree, dir)
    local len = tvb:len()
    local m = pick(tvb, dir)
    local root = tree:add(proto, tvb())
    if not m then
        root:add_proto_expert_info(ex_unknown, "unknown command " .. key_text(tvb))
        root:append_text(": unknown command " .. key_text(tvb))
        return nil, root
    end
    root:append_text(": " .. m.n)
    root:add(pf_message, m.n)
    for _, x in ipairs(m.fx) do
        if x[1] < len and tvb(x[1], 1):uint() ~= x[2] then
            root:add_proto_expert_info(ex_fixed, string.format("byte %d is 0x%02x, %s needs 0x%02x",
                x[1], tvb(x[1], 1):uint(), m.n, x[2]))
        end
    end
    if len < m.min then
        root:add_proto_expert_info(ex_length, m.n .. ": " .. len .. " bytes, at least " .. m.min .. " expected")
    elseif len > m.mi then
        root:add_proto_expert_info(ex_length, m.n .. ": " .. len .. " bytes, at most " .. m.mi .. " expected")
    end
    add_fields(root, tvb, 0, m.f, math.min(len, m.max), m.n)
    return m, root
end

local function append_info(pinfo, text)
    local info = tostring(pinfo.cols.info)
    if info:find("robowire:", 1, true) then
        pinfo.cols.info:append(", " .. text)
    else
        pinfo.cols.info:append(" robowire: " .. text)
    end
end

-- ---------------------------------------------------------------- BLE (GATT)
if P.ble then
    local f_opcode = Field.new("btatt.opcode")
    local host_to_device = { [0x12] = true, [0x52] = true, [0x16] = true, [0xd2] = true }
    local device_to_host = { [0x1b] = true, [0x1d] = true, [0x0b] = true, [0x0d] = true, [0x0f] = true }

    local function direction()
        local ops = { f_opcode() }
        local op = ops[#ops]
        if op == nil then return nil end
        op = op.value
        if host_to_device[op] then return "c" end
        if device_to_host[op] then return "n" end
        return nil
    end

    -- Multi-frame messages: per direction, the frames collected so far (first
    -- pass only); the completed payload is stored under the last frame's number.
    local partial, completed = {}, {}
    function proto.init()
        partial, completed = {}, {}
    end

    local function multiframe(tvb, pinfo, tree, m, dir)
        local mf = P.multiframe
        if not mf or tvb:len() < mf.payload_offset + mf.payload_size then return end
        local key = dir or "?"
        if not pinfo.visited then
            local command = tvb(mf.command_offset, 1):uint()
            local remaining = tvb(mf.remaining_offset, 1):uint()
            local payload = tvb(mf.payload_offset, mf.payload_size):bytes()
            local st = partial[key]
            if st and (st.command ~= command or st.remaining ~= remaining + 1) then st = nil end
            if not st then st = { command = command, data = ByteArray.new(), frames = 0 } end
            st.data:append(payload)
            st.frames = st.frames + 1
            st.remaining = remaining
            if remaining == 0 then
                if st.frames > 1 or command == mf.text_command then
                    completed[pinfo.number] = { command = command, data = st.data, frames = st.frames }
                end
                partial[key] = nil
            else
                partial[key] = st
            end
        end
        local c = completed[pinfo.number]
        if c then
            local whole = c.data:tvb("Reassembled " .. P.title .. " message")
            tree:add(pf_reassembled_frames, c.frames)
            if c.command == mf.text_command then
                local s = whole():stringz()
                tree:add(pf_text, whole(0, whole:len()), s)
                append_info(pinfo, s)
            end
        end
    end

    local function dissect_ble(tvb, pinfo, tree)
        if tvb:len() == 0 then return 0 end
        pinfo.cols.protocol:set(P.name)
        local dir = direction()
        local m, root = dissect_message(tvb, pinfo, tree, dir)
        append_info(pinfo, m and m.n or ("unknown command " .. key_text(tvb)))
        if m and P.multiframe then multiframe(tvb, pinfo, root, m, dir) end
        return tvb:len()
    end
    proto.dissector = dissect_ble

    local uuid_table = DissectorTable.get("bluetooth.uuid")
    for _, uuid in ipairs(P.ble) do uuid_table:add(uuid, proto) end
    -- Captures without GATT discovery: Decode As... on btatt.handle.
    DissectorTable.get("btatt.handle"):add_for_decode_as(proto)
end

-- ---------------------------------------------------------------- byte stream
if P.stream then
    local size = P.stream.size
    local marks = P.stream.marks
    local start = marks[1][2]
    local expect = {}
    for _, x in ipairs(marks) do expect[x[1]] = x[2] end

    -- Per direction: the bytes of a partial frame candidate, each {value, frame number, offset}.
    local pending, results = {}, {}
    function proto.init()
        pending, results = {}, {}
    end

    local function prefix_ok(buf)
        for k = 1, #buf do
            local want = expect[k - 1]
            if want and buf[k][1] ~= want then return false end
        end
        return true
    end

    -- Scans the bytes of one packet, as osp::scanner does: every frame with the
    -- right markers, and after a false start resume at the next byte.
    local function scan(tvb, pinfo, dir)
        local buf = pending[dir] or {}
        local out = { frames = {}, noise = 0, noise_here = {} }
        local number = pinfo.number
        local function drop(b)
            out.noise = out.noise + 1
            if b[2] == number then out.noise_here[#out.noise_here + 1] = b[3] end
        end
        local function resync()
            local from = 2
            while true do
                while from <= #buf and buf[from][1] ~= start do from = from + 1 end
                for k = 1, from - 1 do drop(buf[k]) end
                local rest = {}
                for k = from, #buf do rest[#rest + 1] = buf[k] end
                buf = rest
                if prefix_ok(buf) then return end
                from = 2
            end
        end
        for i = 0, tvb:len() - 1 do
            local b = { tvb(i, 1):uint(), number, i }
            if #buf == 0 then
                if b[1] == start then buf[1] = b else drop(b) end
            else
                buf[#buf + 1] = b
                local k = #buf - 1
                if k == size - 1 then
                    if b[1] == expect[k] then
                        out.frames[#out.frames + 1] = buf
                        buf = {}
                    else
                        resync()
                    end
                elseif expect[k] and b[1] ~= expect[k] then
                    resync()
                end
            end
        end
        pending[dir] = buf
        return out
    end

    local function dissect_stream(tvb, pinfo, tree)
        pinfo.cols.protocol:set(P.name)
        local dir = tostring(pinfo.p2p_dir)
        if not pinfo.visited and not results[pinfo.number] then
            results[pinfo.number] = scan(tvb, pinfo, dir)
        end
        local res = results[pinfo.number]
        if not res then return 0 end
        local names = {}
        for _, fr in ipairs(res.frames) do
            local contiguous = true
            for k = 1, #fr do
                if fr[k][2] ~= pinfo.number or fr[k][3] ~= fr[1][3] + k - 1 then contiguous = false end
            end
            local ftvb
            if contiguous then
                ftvb = tvb(fr[1][3], #fr):tvb()
            else
                local ba = ByteArray.new()
                ba:set_size(#fr)
                for k = 1, #fr do ba:set_index(k - 1, fr[k][1]) end
                ftvb = ba:tvb("Reassembled " .. P.title .. " frame")
            end
            local m = dissect_message(ftvb, pinfo, tree, nil)
            names[#names + 1] = m and m.n or ("unknown command " .. key_text(ftvb))
        end
        if res.noise > 0 then
            local item
            if #res.noise_here > 0 then
                local first, last = res.noise_here[1], res.noise_here[#res.noise_here]
                item = tree:add(pf_noise, tvb(first, last - first + 1), res.noise)
            else
                item = tree:add(pf_noise, res.noise)
            end
            item:append_text(" (not part of any frame)")
            names[#names + 1] = res.noise .. " noise bytes"
        end
        if #names > 0 then
            pinfo.cols.info:set(table.concat(names, ", "))
        else
            pinfo.cols.info:set("partial frame")
        end
        return tvb:len()
    end
    proto.dissector = dissect_stream

    -- Captures with link type USER0 (DLT 147): no option needed.
    DissectorTable.get("wtap_encap"):add(wtap_encaps.USER0, proto)
end
