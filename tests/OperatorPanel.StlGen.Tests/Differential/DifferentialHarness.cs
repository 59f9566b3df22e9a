using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.StlGen.Merge;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.Differential;

/// <summary>
/// The generated handler running in the STL interpreter behind a Freeport port, beside the reference model with the
/// same HandlerConfig and the same initial memory (random V, M, Q, I). Each exchange sends characters on the line and
/// returns what the interpreted handler transmitted and what the reference answers to the messages its RCV would see.
/// Not comparable, so kept out of the random requests (the generator reads <see cref="IsReserved"/> and
/// <see cref="IsVolatileSm"/>): the handler's own V bytes (the reference has no buffer in V), and the SM bytes the CPU
/// or the handler changes by itself while a request is served (SMB0-SMB5 status, flags and received character,
/// SMW22-SMW26 scan times, the port's receive status SMB86/SMB186). Those and the bytes the handler's initialisation
/// writes (SMB30, SMB34, SMB87-SMB94 and the port 1 twins) are copied from the interpreter into the reference before
/// every exchange; all of them are protected against writes, so no write of the panel is masked by the copy.
/// Given a user's program, the harness runs the handler merged into it (<see cref="HandlerMerger"/>): the user's code
/// runs beside the handler, and the bytes it uses (<see cref="User"/>) are kept out of the random requests as well.
/// </summary>
internal sealed class DifferentialHarness
{
    private static readonly TimeSpan Margin = TimeSpan.FromMilliseconds(30);

    private readonly StlPlc _plc;
    private readonly FreeportPort _port;
    private readonly ReferencePlc _reference;
    private readonly HandlerOptions _options;
    private TimeSpan _now = TimeSpan.FromMilliseconds(50);

    /// <param name="inputsOff">Field inputs 0 from power-up instead of random (a user's program that stops on an input).</param>
    public DifferentialHarness(HandlerOptions options, Random random, string? userProgram = null, bool inputsOff = false)
    {
        _options = options;
        var generated = HandlerGenerator.Generate(options);
        if (!generated.Ok)
        {
            throw new InvalidOperationException("not generated: " + string.Join("; ", generated.Diagnostics));
        }

        var merged = userProgram is null ? null : HandlerMerger.Merge(userProgram, options);
        if (merged is { Ok: false })
        {
            throw new InvalidOperationException("not merged: " + string.Join("; ", merged.Errors));
        }

        User = userProgram is null ? UserBytes.None : UserBytes.Of(userProgram);
        var load = StlProgramLoader.Load(merged?.MergedText ?? generated.AwlText, options.Cpu);
        if (load.Program is null)
        {
            throw new InvalidOperationException("not loaded: " + string.Join("; ", load.Diagnostics));
        }

        (ReservedFirst, ReservedLast) = (generated.Stats!.FirstVByte, generated.Stats.LastVByte);
        _plc = new StlPlc(load.Program);
        Line = new LineSettings(options.BaudRate, options.Parity, options.DataBits);
        _port = new FreeportPort(options.Port, _plc.Memory, options.Cpu, Line);
        _plc.AttachPort(_port);
        // The generated handler has neither STOP nor READ CHANGES copies (IDENTIFY: FEATURES 0, COPY_BYTES 0).
        _reference = new ReferencePlc(new HandlerConfig(
            new Station(options.Station), options.Cpu, options.Port, (byte)options.WriteMask, (byte)options.ReplyDelayMs, options.EffectiveBufferStart,
            allowStop: false, copyBytes: 0));
        Fill(random);
        if (inputsOff)
        {
            Poke(ProtocolArea.I, 0, new byte[_plc.InputImage.Length]);
            Array.Clear(_plc.Memory.I);
        }

        _plc.RunUntil(_now);
    }

    public int ReservedFirst { get; }

    /// <summary>Bytes of the user's program in a merged run (none for the handler alone).</summary>
    public UserBytes User { get; }

    /// <summary>The interpreter's memory of an area (the user's code runs there, the reference never sees it).</summary>
    public byte[] Interpreted(ProtocolArea area) => _plc.Memory.Area(area);

    /// <summary>Simulated time of the interpreter.</summary>
    public TimeSpan Now => _plc.Now;

    public int ReservedLast { get; }

    public LineSettings Line { get; }

    public ReferencePlc Reference => _reference;

    public long Instructions => _plc.InstructionsExecuted;

    /// <summary>Sets the same bytes in both PLCs (I through the interpreter's input image).</summary>
    public void Poke(ProtocolArea area, int offset, params byte[] bytes)
    {
        bytes.CopyTo(_reference.Memory.Area(area), offset);
        bytes.CopyTo(area == ProtocolArea.I ? _plc.InputImage : _plc.Memory.Area(area), offset);
    }

    public bool IsReserved(int first, int last) => first <= ReservedLast && last >= ReservedFirst;

    public static bool IsVolatileSm(int offset) => offset <= 5 || offset is (>= 22 and <= 27) or 86 or 186;

    /// <summary>Sends the chunks; returns (interpreted handler's characters, reference's replies), both ASCII.</summary>
    public (string Stl, string Reference) Exchange(IReadOnlyList<WireChunk> chunks)
    {
        CopyCpuOwnedSm();
        var expected = new StringBuilder();
        foreach (var message in ReceiveSplitter.Split(chunks, _options.CharTimeoutMs))
        {
            if (_reference.HandleFrame(message) is { } reply)
            {
                expected.Append(Encoding.ASCII.GetString(reply));
            }
        }

        var at = _now;
        foreach (var chunk in chunks)
        {
            at += chunk.GapBefore;
            _port.Deliver(chunk.Characters, at);
            at += Line.CharacterTime * chunk.Characters.Length;
        }

        var got = new StringBuilder();
        var replyTime = Line.CharacterTime * expected.Length;
        var deadline = at + TimeSpan.FromMilliseconds(_options.ReplyDelayMs + _options.CharTimeoutMs) + Margin + replyTime;
        var step = TimeSpan.FromTicks(Math.Max(TimeSpan.TicksPerMillisecond, Line.CharacterTime.Ticks * 4));
        _plc.RunUntil(at);
        var t = at;
        while (_plc.Fault is null)
        {
            foreach (var c in _port.TakeTransmitted())
            {
                got.Append((char)c.Value);
            }

            var settled = !_port.IsTransmitting && _port.IsReceiving;
            if (settled && (t >= deadline || (expected.Length > 0 && got.Length >= expected.Length)))
            {
                break;
            }

            if (t >= deadline + TimeSpan.FromSeconds(5))
            {
                got.Append(" [port never settled]");
                break;
            }

            t += step;
            _plc.RunUntil(t);
        }

        if (_plc.Fault is { } fault)
        {
            got.Append(" [FAULT ").Append(fault).Append(']');
        }

        _now = t + TimeSpan.FromMilliseconds(1);
        return (MaskScanTimes(got.ToString()), MaskScanTimes(expected.ToString()));
    }

    /// <summary>
    /// The scan times of an IDENTIFY reply (SMW22-SMW26, characters 31-42 of its 62) and so its check characters
    /// (57-60) are not comparable: OP_PANEL builds the reply scans after the request, and those scans change
    /// SMW22-SMW26 in the interpreter after the reference got its copy. Both sides are masked alike.
    /// </summary>
    private static string MaskScanTimes(string replies)
    {
        const int length = 62;
        var text = replies.ToCharArray();
        for (var start = replies.IndexOf('<', StringComparison.Ordinal); start >= 0 && start + length <= text.Length; start = replies.IndexOf('<', start + 1))
        {
            if (text[start + length - 1] == '>' && replies.Substring(start + 5, 2) == "81")
            {
                Array.Fill(text, '*', start + 31, 12);
                Array.Fill(text, '*', start + 57, 4);
            }
        }

        return new string(text);
    }

    private void Fill(Random random)
    {
        Randomize(random, _plc.Memory.V, _reference.Memory.V);
        Randomize(random, _plc.Memory.M, _reference.Memory.M);
        Randomize(random, _plc.Memory.Q, _reference.Memory.Q);
        Randomize(random, _plc.InputImage, _reference.Memory.I);
        Array.Copy(_plc.InputImage, _plc.Memory.I, _plc.Memory.I.Length);
        for (var b = ReservedFirst; b <= ReservedLast; b++)
        {
            (_plc.Memory.V[b], _reference.Memory.V[b]) = (0, 0);
        }
    }

    private static void Randomize(Random random, byte[] a, byte[] b)
    {
        random.NextBytes(a);
        a.CopyTo(b, 0);
    }

    private void CopyCpuOwnedSm()
    {
        var from = _plc.Memory.SM;
        var to = _reference.Memory.SM;
        for (var b = 0; b < to.Length; b++)
        {
            if (b < 30 || b is 30 or 34 or 130 or (>= 86 and <= 94) or (>= 186 and <= 194))
            {
                to[b] = from[b];
            }
        }
    }
}
