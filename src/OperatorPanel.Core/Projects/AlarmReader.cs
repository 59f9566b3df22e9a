using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Projects;

/// <summary>Reads a station's <c>alarms</c>: a flag bit, its text, class and whether it must be acknowledged.</summary>
internal static class AlarmReader
{
    public static ImmutableArray<AlarmDefinition>? ReadAll(JsonFields station, CpuProfile? cpu, LinkProtocol? link, EntryRegistry registry) =>
        station.Entries("alarms", entry =>
        {
            entry.ReportUnknown("flag", "text", "class", "acknowledgementRequired");
            var flag = AddressReader.Read(entry, "flag", cpu, Shape, link: link);
            if (flag is { } f && !registry.ClaimAddress(entry, "flag", "alarms", f))
            {
                flag = null;
            }

            var text = TextRule.AlarmText.Read(entry, "text");
            if (text is not null && string.IsNullOrWhiteSpace(text))
            {
                entry.Problem("text", "the alarm text is empty; the operator would see a blank message");
                text = null;
            }

            var alarmClass = entry.Word("class", AlarmClass.Fault);
            var acknowledge = entry.Bool("acknowledgementRequired", fallback: true);
            return flag is null || text is null || alarmClass is null || acknowledge is null
                ? null
                : new AlarmDefinition(flag.Value, text, alarmClass.Value, acknowledge.Value);
        });

    private static string? Shape(PlcAddress address)
    {
        if (address.Width != AccessWidth.Bit)
        {
            return $"an alarm flag is a bit such as M2.0; {address} is {AddressReader.Kind(address)}";
        }

        return null;
    }
}
