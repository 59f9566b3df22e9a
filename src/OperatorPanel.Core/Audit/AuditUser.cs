namespace OperatorPanel.Core.Audit;

/// <summary>Who runs the panel, as a write's record names them: DOMAIN\user on Windows (the shop PC's login), the user name elsewhere.</summary>
public static class AuditUser
{
    public static string Current { get; } = OperatingSystem.IsWindows() && !string.IsNullOrEmpty(Environment.UserDomainName)
        ? $"{Environment.UserDomainName}\\{Environment.UserName}"
        : Environment.UserName;
}
