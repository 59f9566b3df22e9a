using System.Globalization;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// Reads a station's <c>link</c> object and checks it against what S7-200 Freeport can do (seed 002, Table C-11:
/// SMB30 holds the baud code, 7 or 8 data bits, parity none/even/odd; Freeport always sends one stop bit).
/// </summary>
internal static class LinkReader
{
    public static SerialSettings? Read(JsonFields? fields, CpuProfile? cpu)
    {
        if (fields is null)
        {
            return null;
        }

        fields.ReportUnknown("port", "baud", "parity", "dataBits", "stopBits", "kind");
        var port = fields.String("port");
        if (port is not null && string.IsNullOrWhiteSpace(port))
        {
            fields.Problem("port", "the serial port name is empty; write e.g. COM3 or /dev/ttyUSB0");
            port = null;
        }

        var baud = fields.Int("baud", 9600);
        if (baud is { } b && cpu is not null && cpu.FreeportBaudCode(b) is null)
        {
            var rates = string.Join(", ", cpu.FreeportBaudRates.Select(r => r.Baud).Order());
            fields.Problem("baud", string.Create(CultureInfo.InvariantCulture, $"{cpu.DisplayName} cannot run Freeport at {b} baud; use one of {rates}"));
            baud = null;
        }

        var parity = fields.Word("parity", Parity.None);
        var dataBits = fields.Int("dataBits", 8);
        if (dataBits is not (null or 7 or 8))
        {
            fields.Problem("dataBits", string.Create(CultureInfo.InvariantCulture, $"{dataBits} data bits: a Freeport character has 7 or 8 (SMB30 bit 5)"));
            dataBits = null;
        }

        var stopBits = fields.Int("stopBits", 1);
        if (stopBits is not (null or 1))
        {
            fields.Problem("stopBits", string.Create(CultureInfo.InvariantCulture, $"{stopBits} stop bits: S7-200 Freeport always sends one stop bit; use 1"));
            stopBits = null;
        }

        var kind = fields.Word("kind", LinkKind.Cable);
        if (port is null || baud is null || parity is null || dataBits is null || stopBits is null || kind is null)
        {
            return null;
        }

        return new SerialSettings
        {
            PortName = port,
            BaudRate = baud.Value,
            Parity = parity.Value,
            DataBits = dataBits.Value,
            StopBits = stopBits.Value,
            Kind = kind.Value,
        };
    }

    /// <summary>"9600 8N1 cable", as technicians write line settings.</summary>
    public static string Describe(SerialSettings link) => $"{link.LineText} {JsonWords.Of(link.Kind)}";
}
