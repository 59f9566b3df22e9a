using System.Globalization;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Handler;

/// <summary>The figures every part of the handler needs, worked out once from checked options.</summary>
internal sealed class HandlerContext
{
    public HandlerContext(HandlerOptions options)
    {
        Options = options;
        Layout = new HandlerLayout(options.EffectiveBufferStart, options.CopyBytes);
        Port = options.Port;
        VBytes = HandlerDefaults.VBytes(options.Cpu);
        SmBytes = options.Cpu.TryGetArea(MemoryArea.SM, out var sm) ? sm.ByteCount : 0;
    }

    public HandlerOptions Options { get; }

    public HandlerLayout Layout { get; }

    public HandlerBlockNames Names => Options.Names;

    public int Port { get; }

    public int VBytes { get; }

    public int SmBytes { get; }

    /// <summary>V_BYTES of IDENTIFY: the buffer, the work bytes and the READ CHANGES copies.</summary>
    public int HandlerVBytes => HandlerDefaults.FootprintBytes(CopyBytes);

    /// <summary>COPY_BYTES of IDENTIFY: the READ CHANGES copy area (0 = none).</summary>
    public int CopyBytes => Options.CopyBytes;

    /// <summary>FEATURES of IDENTIFY: bit 0 = 07 STOP included, bit 1 = READ CHANGES copies present, bit 2 = 09 present (always).</summary>
    public int Features =>
        (Options.AllowStop ? HandlerIdentity.StopFeature : 0) | (CopyBytes > 0 ? HandlerIdentity.CopiesFeature : 0) | HandlerIdentity.ChangesOfListsFeature;

    /// <summary>"0" or "1": the PORT operand of RCV and XMT.</summary>
    public string PortOperand => Port.ToString(CultureInfo.InvariantCulture);

    /// <summary>Receive message complete: event 23 (port 0) or 24 (port 1); docs/sources/s7200-facts.md section 5.</summary>
    public int ReceiveEvent => Port == 0 ? 23 : 24;

    /// <summary>Transmit complete: event 9 (port 0) or 26 (port 1).</summary>
    public int TransmitEvent => Port == 0 ? 9 : 26;

    /// <summary>Timed interrupt 0, interval SMB34.</summary>
    public const int DelayEvent = 10;

    /// <summary>SMB30 for port 0, SMB130 for port 1; SMB86-SMB94 and SMB186-SMB194 likewise (seed 002, Tables C-11, C-16).</summary>
    public int SmPort(int port0Byte) => port0Byte + (Port == 0 ? 0 : 100);

    public string SmB(int port0Byte) => "SMB" + SmPort(port0Byte).ToString(CultureInfo.InvariantCulture);

    public string SmW(int port0Byte) => "SMW" + SmPort(port0Byte).ToString(CultureInfo.InvariantCulture);

    /// <summary>
    /// SMB30/SMB130 = pp d bbb mm (seed 002 Table C-11): parity 00 none, 01 even, 11 odd; d 1 = 7 data bits; bbb the
    /// CPU's baud code; mm 01 Freeport.
    /// </summary>
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

    public bool MayWrite(int areaCode) => (Options.WriteMask & (1 << areaCode)) != 0;

    public static string Hex(int value) => "16#" + value.ToString("X2", CultureInfo.InvariantCulture);

    public static string Dec(int value) => value.ToString(CultureInfo.InvariantCulture);

    /// <summary>Characters of a request with <paramref name="payloadBytes"/> after STATION SEQ CMD, as the constant the count is compared with.</summary>
    public static string RequestChars(int payloadBytes) => Dec(ProtocolLimits.RequestChars(payloadBytes));

    /// <summary>Characters of a reply with <paramref name="payloadBytes"/> after STATUS and REQCHECK.</summary>
    public static string ReplyChars(int payloadBytes) => Dec(ProtocolLimits.ReplyChars(payloadBytes));

    /// <summary>The longest reply of a list without its 2D data characters (docs/protocol-v2.md, "Lists", capacity rule).</summary>
    public static string ListReplyChars => Dec(ProtocolLimits.ListReplyChars(0));

    /// <summary>2D + 4N may be at most this: a READ reply of ReplyChars(D) ends before its descriptors at 256 - 4N.</summary>
    public static int ReadReplyRoom => ProtocolLimits.MaxFrameChars - ProtocolLimits.ReplyChars(0);

    /// <summary>A command code as the constant the handler compares CMD with, taken from Core's protocol by name.</summary>
    public static string Dec(CommandCode code) => Dec((byte)code);

    /// <summary>An error code as the two digits docs/protocol-v2.md and the handler's comments use ("04").</summary>
    public static string Digits(ProtocolError error) => ((byte)error).ToString("D2", CultureInfo.InvariantCulture);
}
