using System.Globalization;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Core.Transport;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.V3;

/// <summary>The figures every part of the v3 handler needs, worked out once from checked options.</summary>
internal sealed class Context
{
    public Context(HandlerOptions options)
    {
        Options = options;
        Shape = options.Compact ? HandlerShape.Compact : HandlerShape.Full;
        Layout = new Layout(options.EffectiveV3First, Shape);
        VBytes = options.Cpu.TryGetArea(MemoryArea.V, out var v) ? v.ByteCount : 0;
    }

    public HandlerOptions Options { get; }

    public HandlerShape Shape { get; }

    public Layout Layout { get; }

    public int VBytes { get; }

    public HandlerBlockNames Names => Options.Names;

    public int Port => Options.Port;

    public bool HasList => Shape.HasList;

    /// <summary>
    /// The full handler sends a reply in chunks while its check is computed (a whole list's 137 bytes leave while the
    /// check walks them); the compact handler's replies are at most 33 bytes, so it sends each whole, in one XMT, once
    /// its check is in place: 31 instructions less (no chunk bookkeeping in OP_PANEL or OP_TX), a reply's first byte a
    /// scan or two later (docs/protocol.md section 6).
    /// </summary>
    public bool SendsInChunks => HasList;

    /// <summary>STOP is a full-handler command: the compact handler refuses 08 as unknown (85) whatever the project allows.</summary>
    public bool HasStop => Options.AllowStop && !Options.Compact;

    public string PortOperand => Port.ToString(CultureInfo.InvariantCulture);

    /// <summary>Receive message complete: event 23 (port 0) or 24 (port 1); transmit complete 9 or 26 (docs/sources/s7200-facts.md section 5).</summary>
    public int ReceiveEvent => Port == 0 ? 23 : 24;

    public int TransmitEvent => Port == 0 ? 9 : 26;

    public string SmB(int port0Byte) => "SMB" + SmPort(port0Byte).ToString(CultureInfo.InvariantCulture);

    public string SmW(int port0Byte) => "SMW" + SmPort(port0Byte).ToString(CultureInfo.InvariantCulture);

    public int SmPort(int port0Byte) => port0Byte + (Port == 0 ? 0 : 100);

    /// <summary>SMB30/SMB130 = pp d bbb mm (seed 002 Table C-11): parity, 7 data bits, baud code, 01 Freeport.</summary>
    public int FreeportControl
    {
        get
        {
            var parity = Options.Parity switch { Parity.Even => 0b01, Parity.Odd => 0b11, Parity.None => 0b00 };
            var sevenBits = Options.DataBits == 7 ? 1 : 0;
            var baud = Options.Cpu.FreeportBaudCode(Options.BaudRate) ?? 0;
            return (parity << 6) | (sevenBits << 5) | (baud << 2) | 0b01;
        }
    }

    /// <summary>SMW92: the receive ends this many ms after the last character (docs/protocol.md section 1.5).</summary>
    public int EndTimeoutMs => Options.EffectiveEndTimeoutMs;

    /// <summary>Q, M and V as the write mask says; never I or SM.</summary>
    public bool MayWrite(int areaCode) => (Options.EffectiveV3WriteMask & (1 << areaCode)) != 0;

    public static string Dec(int value) => value.ToString(CultureInfo.InvariantCulture);

    public static string Hex(int value) => "16#" + value.ToString("X2", CultureInfo.InvariantCulture);

    public static string Hex(ReplyStatus status) => Hex((byte)status);

    public static string Dec(Command command) => Dec((byte)command);
}
